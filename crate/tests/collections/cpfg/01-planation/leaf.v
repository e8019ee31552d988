angle factor: 8 
initial color: 127
color increment: 1
initial line width: 5 pixels
line width increment: 0.3
viewpoint: 0,0,30
view reference point: 0,0,0
twist: 0
projection: parallel
front distance: -100.0
back distance: 100.0
scale factor: 0.9
z buffer: on
cue range: 0
shade mode: 1
light direction: 1.0,0.0,0.5
diffuse reflection: 10
tropism direction: 1.0,-0.5,0.0
initial elasticity: 0.00
elasticity increment: 0.0

