angle factor: 21 
initial color: 127
color increment: 64
initial line width: 2.0 pixels
line width increment: 1.0
viewpoint: 0,2,30
view reference point: 0,0,0
twist: 0
projection: parallel
front distance: -10000.0
back distance: 10000.0
scale factor: 0.95
z buffer: on
cue range: 0
shade mode: 3
light direction: 1.0,1.0,0.0
diffuse reflection: 10
tropism direction: -0.005,1.0,0.0
initial elasticity: -0.060
elasticity increment: -0.0001
surface ambient: .15
surface diffuse: .50
surface: w bud.s 1.5 2 4
surface: z bud.s 2.0 2 4
surface: f fruit.s 1.8 2 4


