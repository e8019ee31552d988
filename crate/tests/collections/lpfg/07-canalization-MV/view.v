projection: parallel
front distance: 100.0
back distance: -100.0
scale: 0.95
z buffer: off
render mode: filled
line style: pixel
surface: petal.s
window: FlowerHead 0 0 0.4 1.0
window: Histogram 0.4 0.0 0.6 1.0
view: 0 0 0 0 5.11489 0.977504 -1.38001 0

