executable: chiba -e tree.e light.spec
communication type: pipes
turtle position:P:%.4g %.4g %.4g
verbose: off
