angle increment: 20 
initial color: 1
color increment: 1
initial line width: 0.02
line width increment: 0
viewpoint: 0,0,1
view reference point: 0,0,0
viewing angle: 45
/*box: x: -4.3869,4.24187 y: 0,11.0538 z: -4.35336,4.38072*/
twist: 0
projection: parallel
front distance: -10
back distance: 10.0
scale factor: 0.95
z buffer: on
cue range: 0
render mode: shaded
line style: cylinder
tapered lines: on
twist of cylinders: on
contour: 1 leaf.con
/* light direction: 4.0,5.0,8.0 */
light: V: 0.5,1.0,3.0
light: V: -0.5,-1.0,-3.0 A: 0.0 0.0 0.0 D 0.7 0.7 0.7 S: 0.7 0.7 0.7
diffuse reflection: 16
/*
polygonization level: 4
*/
contour sides: 14
/*
tropism: T: 0.0 -1.0 0.0
tropism: T: 0.0  1.0 0.0  A:90
torque:  T: 0.0  1.0 0.0
*/
font:  -*-courier-*-r-*-*-26-*-*-*-*-*-*-*
/* light: O: -4.0 5.0 8.0 A:0 0 0 D: 2 2 2 */
/*light: O: 4.0 5.0 8.0  A:0 0 0 D: 1 0.3 0.3  P: -4 -4 -8 0 4 */
function: width.func 100
function: density.func 100
function: turn.func 100
function: bend.func 100
function: torque.func 100
function: bang.func 100
function: lwidth.func 100
function: ldensity.func 100
function: lturn.func 100
function: leaflet_width.func 100
function: stem_width.func 100
function: lbend.func 100
function: asym.func 100
function: lenscale.func 100
function: color.func 100
