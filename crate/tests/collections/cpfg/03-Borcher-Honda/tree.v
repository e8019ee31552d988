angle factor: 12
initial color: 16
color increment: 1
initial line width: .1
line width increment: .1
viewpoint: 0,0,30
view reference point: 0,0,0
twist: 0
projection: parallel
front distance:100.0
back distance: -100.0
scale factor: .8
z buffer: on
cue range: 0
shade mode: 1 
font: -*-*-*-r-*-*-10-*-*-*-*-*-*-*
light direction: -1.0,1.0,1.0
diffuse reflection: 10
tropism direction: 0.0000,-1.0000,0.0000
initial elasticity: 0.0000
elasticity increment: 0.0000




