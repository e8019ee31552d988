executable: honda81 -e fractal.e density.spec
communication type: files
turtle position: P: %f %f %f
