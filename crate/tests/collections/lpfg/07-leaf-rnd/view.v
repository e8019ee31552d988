line style: cylinder
z buffer: on
surface: leaf.s
render mode: shaded
