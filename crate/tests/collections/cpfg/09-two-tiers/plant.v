angle factor: 12
initial color: 1
color increment: 1
initial line width: 0.072   /* 0.06, 0.72, or 0.08 */
line width increment: .5
viewpoint: 1.1,-60,0
view reference point: 1.1,0,0
viewing angle: 10
projection: perspective
front distance:0.1
back distance: 1000.0
scale factor: 0.95
z buffer: on
render mode: shaded
line style: cylinder
contour sides: 24
light: V: 10 -10 5
