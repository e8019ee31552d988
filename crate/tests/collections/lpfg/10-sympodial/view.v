line style: cylinder
z buffer: on
render mode: shaded
projection: parallel

