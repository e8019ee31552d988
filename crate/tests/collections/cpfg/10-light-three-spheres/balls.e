executable: chiba -e balls.e light.spec
communication type: memory
turtle position:P:%.4g %.4g %.4g
verbose: off
