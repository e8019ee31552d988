angle factor: 12 
initial color: 3
initial line width: 0.1 
line width increment: 0.1
viewpoint: 4,-5,30
view reference point: 0,0,0
twist: 0
projection: parallel
front distance: -1000.0
back distance: 1000.0
scale factor: 0.90
z buffer: on
render mode: shadows
line style: cylinder
light direction: 2.0,1.3,1.5
tropism direction: 0.0,-2.0,0
surface: p petal.s 2.75
surface: c calyx.s 2.0
function: br_ang.func 100
function: elas.func 100

shadow map: size: 4096
