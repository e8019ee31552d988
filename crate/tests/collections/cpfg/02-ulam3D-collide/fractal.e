executable: honda81 density.spec
communication type: files
turtle position:P:%.4f %.4f %.0f
