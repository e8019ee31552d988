angle factor: 6
initial color: 1 
color increment: 0
initial line width: 2
line width increment: 0
viewpoint: 0,0,1
view reference point: 0,0,0
twist: 0
projection: parallel
front distance: -100000.0
back distance: 100000.0
scale factor: 0.9
z buffer: off
cue range: 0
/*
   render mode: fast / filled / interpolated / flat / shaded / wireframe
   line style: pixel / cylinder / polygon
   tappered lines: on/off
*/
render mode: filled
line style: pixel
light direction: 1.0, 1.0, 1.0
diffuse reflection: 0
tropism direction: 0.0,1.0,0.0
initial elasticity: 0.0
elasticity increment: 0.0
