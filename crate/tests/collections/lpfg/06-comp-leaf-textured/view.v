line style: cylinder
z buffer: on
surface: leaf.s 1 10 10 0
render mode: shaded
texture: leaft.png
