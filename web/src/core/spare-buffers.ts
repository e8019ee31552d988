// Array buffers made ahead for a big build's copy out of WebAssembly memory. A new buffer of tens
// of megabytes is fresh memory, which the operating system maps page by page as it is first
// written: copying a million-vertex plant's mesh (about 54 MB) took 33 ms into new buffers and 5 ms
// into buffers whose pages were already touched (Chromium, 2026-11-27), about half of the build
// worker's time outside the core. The build worker makes these while it waits for the next edit,
// sized as the last build's arrays (an edit of a big plant seldom changes them), and the facade
// (./build.ts) copies into them; each is taken once and leaves with the build (transferred).

/** Arrays smaller than this are copied into new buffers: their pages cost little. */
export const MIN_SPARE_BYTES = 1 << 20;

/**
 * At most this many bytes of spares are held: enough for a plant of about a million vertices (1.24d
 * at n = 10 needs 61 MB, its segments' ends and colours and its sketch's lines included), where the
 * pages cost 25 ms; bigger plants get some of theirs.
 */
export const MAX_SPARE_BYTES = 64 << 20;

/** Bytes of a spare whose pages one task touches, so a build asked meanwhile waits little. */
const TOUCH_BYTES_PER_TASK = 8 << 20;

/** Page size to touch at (the smallest of the platforms the studio runs on). */
const PAGE = 4096;

export class SpareBuffers {
  private spares: ArrayBuffer[] = [];
  /** The spares whose pages are still to be touched, each from byte `from`. */
  private untouched: { spare: ArrayBuffer; from: number }[] = [];
  private timer: ReturnType<typeof setTimeout> | undefined;

  constructor(private readonly schedule: (task: () => void) => ReturnType<typeof setTimeout> = (task) => setTimeout(task, 0)) {}

  /**
   * A spare of at least `bytes` and at most half as much again, no longer held here; `undefined`
   * when there is none (or `bytes` is under {@link MIN_SPARE_BYTES}).
   */
  take(bytes: number): ArrayBuffer | undefined {
    if (bytes < MIN_SPARE_BYTES) return undefined;
    const k = this.spares.findIndex((spare) => spare.byteLength >= bytes && spare.byteLength <= 1.5 * bytes);
    if (k < 0) return undefined;
    const [spare] = this.spares.splice(k, 1);
    this.untouched = this.untouched.filter((u) => u.spare !== spare);
    return spare;
  }

  /**
   * Holds spares of these sizes (bytes; those under {@link MIN_SPARE_BYTES} left out, and none
   * past {@link MAX_SPARE_BYTES} in all) in place of the ones held, and touches their pages a few
   * megabytes per task.
   */
  prepare(sizes: readonly number[]): void {
    let total = 0;
    const wanted = sizes.filter((bytes) => bytes >= MIN_SPARE_BYTES && (total += bytes) <= MAX_SPARE_BYTES);
    // Spares of a wanted size are kept (taken by nothing since they were made); the rest go.
    const kept: ArrayBuffer[] = [];
    const made: ArrayBuffer[] = [];
    const free = [...this.spares];
    for (const bytes of wanted) {
      const k = free.findIndex((spare) => spare.byteLength === bytes);
      if (k >= 0) kept.push(...free.splice(k, 1));
      else made.push(new ArrayBuffer(bytes));
    }
    this.spares = [...kept, ...made];
    this.untouched = [...this.untouched.filter((u) => kept.includes(u.spare)), ...made.map((spare) => ({ spare, from: 0 }))];
    if (this.untouched.length > 0 && this.timer === undefined) this.timer = this.schedule(() => this.touch());
  }

  /** Bytes held. */
  get bytes(): number {
    return this.spares.reduce((sum, spare) => sum + spare.byteLength, 0);
  }

  /** Writes one byte per page of the next few megabytes of untouched spares. */
  private touch(): void {
    this.timer = undefined;
    let budget = TOUCH_BYTES_PER_TASK;
    while (budget > 0 && this.untouched.length > 0) {
      const next = this.untouched[0];
      const bytes = new Uint8Array(next.spare);
      const end = Math.min(bytes.length, next.from + budget);
      for (let i = next.from; i < end; i += PAGE) bytes[i] = 0;
      budget -= end - next.from;
      next.from = end;
      if (end === bytes.length) this.untouched.shift();
    }
    if (this.untouched.length > 0) this.timer = this.schedule(() => this.touch());
  }
}
