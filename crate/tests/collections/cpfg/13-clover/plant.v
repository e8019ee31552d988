angle factor: 60
initial color: 1 
color increment: 1
initial line width: 0.3
line width increment: 0
/*viewpoint: 0,0,1
box: x: -50,50 y: -50,50 z: -1,1
view reference point: 0,0,0 */
viewpoint: 0,0,220
view reference point: 0,0,0
viewing angle: 26.5
twist: 0
projection: perspective
front distance: 160
back distance: 280.0
scale factor: 1
z buffer: on
cue range: 0
render mode: filled
line style: cylinder
contour sides: 12
light direction: 1.0, 1.0, 1.0
texture: F: light08.rgb H: l L:l
tropism: T: 0.0  0.0 -1.0
tropism: T: 0.0  0.0 1.0  A:90
torque:  T: 0.0  0.0 1.0
tropism: T: 0.0  0.0 1.0
