angle increment: 45 
initial line width: 0.5 /* world space units */
initial color: 1
color increment: 1
projection: perspective
view reference point: 0,7,0
viewpoint: 0,5,20
viewing angle: 40
front distance: 10      /* why so small? a bug? */
back distance: 40      /* why so small? a bug? */
scale factor: 0.9800
z buffer: on
line style: cylinder
render mode: shaded
light: V: 1,0.5,1
/* light: V: -1,-0.5,-1 D: 0.7 0.7 0.7 */


