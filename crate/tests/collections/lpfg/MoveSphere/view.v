render mode: shaded
z buffer: on
line style: cylinder
light: V: 1 1 1
contour sides: 10
//projection: perspective
projection: parallel
contour sides: 20
