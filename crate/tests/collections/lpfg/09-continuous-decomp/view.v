/* sample viewing/rendering parameters */
scale factor: 0.9 // this is the default
// line style is: pixel, polygon, or cylinder 
line style: pixel // this is the default
// render mode: filled, wireframe, or shaded
render mode: wireframe  // default is filled
