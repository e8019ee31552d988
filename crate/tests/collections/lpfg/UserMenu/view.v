z buffer: on
render mode: shaded
contour sides: 64
