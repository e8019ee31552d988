angle increment: 45
initial color: 1 
color increment: 1
initial line width: 4 pixels
scale factor: 0.9000
contour sides: 16
render mode: filled

