executable: ./obcheck -e enviro.e obstacles.dat
communication type: files
turtle position:P:%.4f %.4f
