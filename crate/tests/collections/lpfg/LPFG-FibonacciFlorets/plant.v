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
view: 0 0 0 0 6.11489 0.977504 -1.38001 0
// view: 0 pan: 0 0 0 scale: 0.5
// winfont: "Arial" 14
// font: -*-Times-bold-italic-*-18--120-75-75-p-68-iso8859-1
font: -*-Arial-*-r-*-14--120-75-75-p-68-iso8859-1
