line style: pixel
z buffer: on
render mode: shaded
