angle factor: 4
initial color: 1
color increment: 0
initial line width: 0.1 
line width increment: .5
view reference point: 0,0,0
viewpoint: 0,15,30
viewing angle: 20
projection: perspective
front distance: 0.1
back distance: 1000.0
scale factor: 7
z buffer: on
render mode: shaded
/* fast | filled | interpolated | flat | shaded | wireframe */
line style: cylinder
/* pixel | cylinder | polygon */
tapered lines: on
polygonization level: 2
light: V: 1.0, 0.5, 0.5
