projection: parallel
viewpoint: 0,0,1
view reference point: 0,0,0
front distance: -10
back distance: 10.0
scale factor: 0.95

z buffer: on
render mode: shaded
light: V: 0.5,1.0,3.0

line style: cylinder
twist of cylinders: on
polygonization level: 3

function set: functions.fset
contour: 1 leaf.con