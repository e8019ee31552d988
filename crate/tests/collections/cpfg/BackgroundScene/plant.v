initial line width: 0.1
viewpoint: 0,3,7
view reference point: 0,2,0
projection: perspective
front distance: 0.01
back distance: 200.0
viewing angle: 30
scale factor: 0.6
z buffer: on
render mode: shaded
line style: cylinder
light direction: -4.0,5.0,8.0
contour sides: 18
background scene: background.dat

