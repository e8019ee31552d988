executable: ecosystem -e tree.e density.spec
communication type: files
turtle position:P:%.4f %.4f %.4f
