projection: parallel
front distance:1000.0
back distance: -1000.0
scale: 0.98
z buffer: on
render mode: filled
light: O: 10 10 -5
