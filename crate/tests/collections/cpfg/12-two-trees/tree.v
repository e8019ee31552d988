angle factor: 12
initial color: 1
color increment: 1
initial line width: 0.06
line width increment: .5
viewpoint: 0,4,-95
view reference point: 0,5.9,0
viewing angle: 10
projection: perspective
front distance:0.1
back distance: 1000.0
scale factor: 1.0
z buffer: on
render mode: shaded
line style: cylinder
tapered lines: on
contour sides: 12
light: O: 1000 1000 -1500
interpretation step: 250
interpretation past %: off
interpretation step: -1
