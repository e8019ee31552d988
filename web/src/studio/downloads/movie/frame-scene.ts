// The scene a movie's frames are drawn from (the fixed interface of issue 45, docs in
// /work/briefs/i45/interfaces.md): the growth time and turntable posed, then a frame drawn at a size.
// The studio's is the view's (./view-scene.ts); tests may give any.

/** Frames for video, GIF and PNG sequences. */
export interface FrameScene {
  /** Poses the scene for frame time `t` (growth time, and the turntable's angle). */
  at(t: number, turn: number): void | Promise<void>;
  /** Draws the posed scene into a canvas of width × height (the view's camera and look). */
  draw(width: number, height: number): HTMLCanvasElement | OffscreenCanvas;
}
