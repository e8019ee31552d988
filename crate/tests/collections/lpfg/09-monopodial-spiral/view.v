line style: cylinder
z buffer: on
render mode: shaded
projection: parallel
surface: leaf.s
stropism: 0.0 1.0 0, 0.05
light: V: 5 3 1 D: 0.3 0.5 0.3
light: V: 0 -1 0 D: 0.8 0.7 0.3
light: V: 0 1 0 D: 0.3 0.5 0.3
corrected rotation: on
