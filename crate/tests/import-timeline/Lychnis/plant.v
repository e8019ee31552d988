scale factor: 0.9
z buffer: on
projection: parallel
// projection: 29perspective
// view: 0 dir: 0 0 -1 fov: 45 scale: 1.00
render mode: shadows
// render mode: shaded
line style: cylinder
contour sides: 8
light: V: 1.0 1.5 0.5
tropism: T: 0.0 1.0 0.0

surface: petal.s 1 4 6
surface: leaf.s 1 6 12

texture: leafs.png /* texture on the entire surface */
texture: flowertexture.png /* texture on the entire surface */
