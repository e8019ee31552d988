executable: honda81 -e plant.e density.spec
communication type: files
turtle position: P: %f %f %f
