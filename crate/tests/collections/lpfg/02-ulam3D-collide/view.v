projection: parallel
front distance: -50.0
back distance: 50.0
scale: 0.98
z buffer: on
render mode: shaded
line style: cylinder
light: O: 10 10 -5
light: O: -10 -10 5
