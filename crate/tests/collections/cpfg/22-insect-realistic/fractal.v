angle factor: 8
initial color: 1 
color increment: 1
initial line width: 0.5
line width increment: 0
viewpoint: 0,-0.5,1
view reference point: 0,-0.5,0
box: x: -10,10 y: -57,70 z: -1,1
twist: 0
projection: parallel
front distance: -100.0
back distance: 100.0
scale factor: 1
z buffer: on
cue range: 0
shade mode: 3
light direction: 1.0, 1.0, 1.0
diffuse reflection: 0
tropism direction: 0.0,1.0,0.0
initial elasticity: 0.0
elasticity increment: 0.00
polygonization level: 3




