executable: honda81 density.spec
communication type: files
turtle position: %.4f %.4f %.4f
