z buffer: off
line style: polygon
corrected rotation: on

window: View1 0.0 0.0 1.0 0.5
window: View2 0.0 0.5 0.5 0.5
window: View3 0.5 0.5 0.5 0.5
window border: 15 0 255 255

winfont: "Times" 24 
