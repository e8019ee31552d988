angle increment: 90
initial color: 1
color increment: 1
initial line width: 0.5
line width increment: 0
viewpoint: 0,0,-1
box: x: -16,16 y: -16,16 z: -1,1
view reference point: 0,0,0
projection: parallel
front distance: 1000.0
back distance: -1000.0
scale factor: 0.98
z buffer: on
render mode: filled /* filled or shaded */
line style: polygon /* polygon or cylinder */
light: O: 10 10 -5
