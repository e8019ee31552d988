line style: cylinder
z buffer: on
render mode: shaded
projection: parallel
surface: leaf.s
corrected rotation: off
light: V: 0.0 1 0.5 
light: V: 0 -1 -0.0 D: 0.1 0.1 0.1
