angle factor: 4 
initial color: 127
color increment: 1
initial line width: 0.1
line width increment: 0.035
box: x: -4,4 y: -2,7 z:-4,4
viewpoint: 0,0,300
view reference point: 0,0,0
twist: 0
projection: parallel
front distance: -1000.0
back distance: 1000.0
scale factor: 1.0
z buffer: on
cue range: 0
shade mode: 1
light direction: 5.0,1.0,0.0
diffuse reflection: 1
contour sides: 16
