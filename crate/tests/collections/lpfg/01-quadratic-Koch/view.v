render mode: wireframe
