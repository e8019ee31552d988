z buffer: on
line style: cylinder
render mode: shaded
front distance: 100
back distance: -100

light: V: 0.2 100 1

texture: Terrain.rgb
terrain: Terrain.patch 5 1 10 on 0 1.0 1.0

