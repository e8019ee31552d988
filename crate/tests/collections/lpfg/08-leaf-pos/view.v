line style: cylinder
z buffer: on
surface: leaf.s
render mode: shaded
stropism: 0.0 1.0 0.0, 0.1
