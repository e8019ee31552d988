angle increment: ?
initial line width: 1 pixels
initial color: 1
scale factor: 0.9000


