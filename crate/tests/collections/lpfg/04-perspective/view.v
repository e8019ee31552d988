line style: cylinder
z buffer: on
render mode: shaded
projection: perspective
view: 0 shift: 8 fov: 90
