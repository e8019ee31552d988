angle factor: 40
initial color: 1
color increment: 1
initial line width: 1
line width increment: 2
viewpoint: 0,0,30
view reference point: 0,0,0
projection: parallel
front distance: -100.0
back distance: 100.0
scale factor: 0.98
z buffer: on
render mode: shaded
line style: cylinder
light: V: 5 3 5
light: V: -5 -3 -5 
function: internode.func 100
function: leaf-length.func 100
function: int-pos.func 100
function: leaf-pos.func 100
surface: l leaf.s 1 8 4
tropism: T: 0,1,0 E: 0.2