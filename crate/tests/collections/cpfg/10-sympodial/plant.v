angle factor: 40
initial color: 1
color increment: 1
initial line width: 1
line width increment: 2
viewpoint: 0,0,30
view reference point: 0,0,0
twist: 0
projection: parallel
front distance: -100.0
back distance: 100.0
scale factor: 1.0
z buffer: on
render mode: shaded
line style: cylinder
contour sides: 8
light: V: 5 3 1 D: 0.3 0.5 0.3
light: V: 0 -1 0 D: 0.8 0.7 0.3
light: V: 0 1 0 D: 0.3 0.5 0.3
tropism direction: 0,1.0,0
initial elasticity: 0.15
elasticity increment: 0.0
function: internode.func 100
function: flower.func 100
