executable: clover -e enviro.e enviro.spec
communication type: memory
turtle position:P:%g %g %g
