angle factor: 12
initial color: 127
color increment: 1
initial line width: 2.0 pixels
line width increment: 2.0
viewpoint: 0,0,30
view reference point: 0,0,0
twist: 0
projection: parallel
front distance: -10000000.0
back distance: 10000000.0
scale factor: 0.8
z buffer: off
cue range: 0
shade mode: 3
light direction: 1.0,0.0,0.0
diffuse reflection: 10
tropism direction: 0.0,1.0,0.0
initial elasticity: 0.00
elasticity increment: 0.00

