angle increment: 45 
initial line width: 0.5 /* world space units */
initial color: 1
color increment: 1
front distance: -100    /* try -1 or -10000 */
back distance: 100      /* try -1 or -10000 */
scale factor: 0.9800
z buffer: on            /* on or off */
line style: cylinder    /* pixel, polygon or cylinder */
render mode: shaded     /* shaded or wireframe */
light: V: 1,0.5,1
light: V: -1,-0.5,-1 D: 0.7 0.7 0.7


