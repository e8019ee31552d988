render mode: shaded
z buffer: on
light: V: 1 1 1
projection: parallel
contour sides: 20
box: 0 0 20 0 20 -10 10
