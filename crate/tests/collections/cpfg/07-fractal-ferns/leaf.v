angle increment: 45
initial color: 1 
color increment: 1
initial line width: 2 pixels
scale factor: 0.9000
