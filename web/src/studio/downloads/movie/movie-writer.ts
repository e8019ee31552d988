// What every movie file is written through: frames in, one after another, a file out.

/** A movie file being written. */
export interface MovieWriter {
  /** Adds frame `index` (from 0, in order), drawn in `frame`; resolves when the writer can take the next. */
  add(frame: HTMLCanvasElement | OffscreenCanvas, index: number): Promise<void>;
  /** The whole file, once every frame has been added. */
  finish(): Promise<Blob>;
  /** Stops at once (a cancel) and lets go of what was written. */
  close(): void;
}
