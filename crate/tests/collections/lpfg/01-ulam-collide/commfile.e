executable: honda81 -e commfile.e density.spec
communication type: files
turtle position: P: %f %f %f
