angle factor: 40
initial color: 1
color increment: 1
initial line width: 1
line width increment: 2
viewpoint: 0,0,40
view reference point: 0,6.5,0
projection: perspective
front distance: 10
back distance: 100.0
viewing angle: 20
scale factor: 0.98
z buffer: on
render mode: shaded
line style: cylinder
light: V: 5 3 5
// light: V: -5 -3 -5 
tropism direction: 0,1,0
initial elasticity: 0.0
function: internode.func 100
function: leaf-length.func 100
surface: l leaf.s 1 10 6
texture: F: leaft.png H:n L:n E:m S: /* texture on the entire surface */
