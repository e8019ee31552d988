angle factor: 12
initial color: 1
color increment: 1
initial line width: 0.06
line width increment: .5
viewpoint: 0,0,1 /* originally 0,6,-80  */
view reference point: 0,0,0
projection: parallel
front distance: -100
back distance: 1000.0
scale factor: 0.95
z buffer: on
render mode: shaded
contour sides: 24
light: V: 50 100 0
