angle factor: 40 
initial color: 3
color increment: 1
initial line width: 0.1 s
line width increment: 0.00
viewpoint: 0,0,5
view reference point: 0,0,0
twist: 0
projection: parallel
front distance: 0.01
back distance: 200.0
scale factor: 0.9
z buffer: on
cue range: 0
shade mode: 6
render mode: shaded
line style: cylinder
tapered lines: on
light direction: -4.0,5.0,8.0
diffuse reflection: 16
contour sides: 8
tropism: T: 0.0 -1.0 0.0
tropism: T: 0.0  1.0 0.0  A:90
torque:  T: 0.0  1.0 0.0
surface ambient: .1
surface diffuse: 0.85
font:  -*-courier-*-r-*-*-24-*-*-*-*-*-*-*
background scene: background.dat

