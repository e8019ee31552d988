line style: pixel
render mode: filled
z buffer: on

