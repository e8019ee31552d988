angle increment: 20 
initial color: 1
color increment: 1
initial line width: 0.02
line width increment: 0
viewpoint: 0,0,1
view reference point: 0,0,0
twist: 0
projection: parallel
front distance: -100
back distance: 100.0
scale factor: 0.95
z buffer: on
cue range: 0
render mode: shaded
line style: cylinder
tapered lines: on
twist of cylinders: on
contour: 1 leaf.con
light: V: 0.5,1.0,2.0
light: V: -0.5,-1.0,-2.0 A: 0.6 0.6 0.6 D 0.6 0.6 0.6 S: 0.6 0.6 0.6
diffuse reflection: 16
contour sides: 14
font:  -*-courier-*-r-*-*-26-*-*-*-*-*-*-*
function: int_length.func 100
function: int_width.func 100
function: curvature.func 100
function: leaf_length.func 100
function: leaf_width.func 100
function: brangle.func 100
