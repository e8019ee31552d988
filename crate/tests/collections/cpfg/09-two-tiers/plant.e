executable: honda81 -e plant.e density.spec
communication type: memory
turtle position:P:%.4f %.0f %.4f
