initial line width: 0.1
viewpoint: 0,0,300
view reference point: 0,0,0
projection: parallel
front distance: -100000.0
back distance: 100000.0
scale factor: 0.95
z buffer: on
render mode: filled
line style: cylinder
contour sides: 16
tropism:  T: 0.0 1.0 0.0

