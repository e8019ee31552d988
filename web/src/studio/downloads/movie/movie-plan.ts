// Movies of the growth: what the dialog's choices mean, frame by frame, and whether they make a
// movie this page can write. Pure: the times and turns of the frames, the limits, the file names.

/** The files a movie is written as: a video (WebM, MP4), an animated GIF, or a zip of numbered PNGs. */
export type MovieFormat = 'webm' | 'mp4' | 'gif' | 'png';

/** How long the movie lasts: `seconds` in all, or `seconds` per derivation step of the range. */
export type MovieTiming = { kind: 'duration'; seconds: number } | { kind: 'per-step'; seconds: number };

/** The choices of the movie dialog, read. */
export interface MovieOptions {
  format: MovieFormat;
  width: number;
  height: number;
  /** Frames per second. */
  fps: number;
  timing: MovieTiming;
  /** The range of growth time played, in derivation steps: from `from` to `to` (`from < to`, or equal for a still plant). */
  from: number;
  to: number;
  /** One whole turn of the camera about the plant over the movie. */
  turntable: boolean;
}

/** A movie that can be written: its options and its number of frames. */
export interface MoviePlan extends MovieOptions {
  frames: number;
}

/** What a format allows: the largest side, and the most pixels of all frames together. */
export interface FormatLimits {
  label: string;
  /** The label with its article, for messages: `an animated GIF`. */
  noun: string;
  /** The frame rates offered (a GIF's delays are whole hundredths of a second). */
  rates: readonly number[];
  maxSide: number;
  /** Frames × width × height at most: what the page holds while it writes the file. */
  maxPixels: number;
}

/** The formats' limits (the page holds the whole file, and a GIF is big and slow to write). */
export const FORMATS: Record<MovieFormat, FormatLimits> = {
  webm: { label: 'WebM video', noun: 'a WebM video', rates: [24, 25, 30, 60], maxSide: 3840, maxPixels: 4e10 },
  mp4: { label: 'MP4 video', noun: 'an MP4 video', rates: [24, 25, 30, 60], maxSide: 3840, maxPixels: 4e10 },
  gif: { label: 'Animated GIF', noun: 'an animated GIF', rates: [10, 20, 25], maxSide: 1280, maxPixels: 6e7 },
  png: { label: 'PNG sequence', noun: 'a PNG sequence', rates: [10, 12, 24, 25, 30, 60], maxSide: 3840, maxPixels: 1e9 },
};

/** The most frames of any movie: ten minutes at 30 frames a second. */
export const MAX_FRAMES = 18_000;
/** The smallest side of a frame, in pixels. */
export const MIN_SIDE = 16;

/** The sizes offered, the GIF's default first among the small ones. */
export const SIZE_PRESETS = [
  { label: '1280 × 720 (HD)', width: 1280, height: 720 },
  { label: '1920 × 1080 (Full HD)', width: 1920, height: 1080 },
  { label: '640 × 360', width: 640, height: 360 },
  { label: '1080 × 1080 (square)', width: 1080, height: 1080 },
  { label: '480 × 480 (square)', width: 480, height: 480 },
  { label: '480 × 270 (small, for slides)', width: 480, height: 270 },
] as const;

/** The number of frames of a movie of `options` (at least one). */
export function frameCount(options: MovieOptions): number {
  const steps = Math.abs(options.to - options.from);
  const seconds = options.timing.kind === 'duration' ? options.timing.seconds : options.timing.seconds * steps;
  return Math.max(1, Math.round(seconds * options.fps));
}

/**
 * The growth time of frame `index` of `frames`: the first frame shows `from`, the last `to` (the
 * whole plant of the range, held as the movie ends), evenly between.
 */
export function frameTime(index: number, frames: number, from: number, to: number): number {
  if (frames <= 1) return to;
  return from + ((to - from) * index) / (frames - 1);
}

/**
 * The turntable's angle at frame `index` of `frames`, in radians: one whole turn over the movie,
 * the last frame one frame's turn short of the first, so that a looped movie turns on smoothly.
 */
export function frameTurn(index: number, frames: number, turntable: boolean): number {
  return turntable ? (2 * Math.PI * index) / frames : 0;
}

/** The duration in seconds a movie of `frames` at `fps` plays for. */
export function movieSeconds(frames: number, fps: number): number {
  return frames / fps;
}

const count = new Intl.NumberFormat('en-US', { maximumFractionDigits: 1 });

/**
 * Checks `options` for a movie of a plant grown over `[0, span]` (span null: a plant without
 * growth times, shown whole) at most `maxSide` pixels a side (the GPU's), and says what is wrong
 * in words the dialog shows.
 */
export function planMovie(options: MovieOptions, span: number | null, maxSide = Infinity): { ok: true; plan: MoviePlan } | { ok: false; message: string } {
  const limits = FORMATS[options.format];
  const side = Math.min(limits.maxSide, maxSide);
  const { width, height, fps, timing, from, to } = options;
  const whole = (n: number) => Number.isInteger(n) && n >= MIN_SIDE && n <= side;
  if (!whole(width) || !whole(height)) return { ok: false, message: `Size: width and height must be whole numbers from ${MIN_SIDE} to ${side} for ${limits.noun}` };
  if (options.format === 'webm' || options.format === 'mp4') {
    if (width % 2 !== 0 || height % 2 !== 0) return { ok: false, message: 'Size: a video’s width and height must be even numbers' };
  }
  if (!limits.rates.includes(fps)) return { ok: false, message: `Frame rate: ${limits.noun} is written at ${limits.rates.join(', ')} frames a second` };
  if (!(timing.seconds > 0) || !Number.isFinite(timing.seconds)) {
    return { ok: false, message: timing.kind === 'duration' ? 'Duration: give a number of seconds above 0' : 'Seconds per step: give a number above 0' };
  }
  const end = span ?? 0;
  if (span !== null && !(Number.isFinite(from) && Number.isFinite(to) && from >= 0 && to <= end && from <= to)) {
    return { ok: false, message: `Time range: from and to must be steps between 0 and ${end}, from not after to` };
  }
  if (span !== null && from === to && timing.kind === 'per-step') {
    return { ok: false, message: 'Time range: from and to are the same step; give a range, or the length in seconds in all' };
  }
  const chosen: MovieOptions = span === null ? { ...options, from: 0, to: 0, timing: asDuration(timing) } : options;
  const plan: MoviePlan = { ...chosen, frames: frameCount(chosen) };
  if (plan.frames > MAX_FRAMES) {
    return { ok: false, message: `That is ${plan.frames.toLocaleString('en-US')} frames; a movie has at most ${MAX_FRAMES.toLocaleString('en-US')}: make it shorter or slower` };
  }
  const pixels = plan.frames * width * height;
  if (pixels > limits.maxPixels) {
    const fit = Math.floor(Math.sqrt(limits.maxPixels / plan.frames / (width * height)) * 100);
    return {
      ok: false,
      message:
        `${capital(limits.noun)} of ${plan.frames.toLocaleString('en-US')} frames at ${width} × ${height} is ${count.format(pixels / 1e6)} million pixels; ` +
        `the most is ${count.format(limits.maxPixels / 1e6)} million: make it smaller (about ${Math.max(1, fit)}% of this size) or shorter`,
    };
  }
  return { ok: true, plan };
}

/** A plant without growth times has no steps to give seconds to: its movie lasts the seconds given. */
function asDuration(timing: MovieTiming): MovieTiming {
  return { kind: 'duration', seconds: timing.seconds };
}

function capital(text: string): string {
  return text.charAt(0).toUpperCase() + text.slice(1);
}

/** The file a movie of the plant `name` is saved as: `abop-1.24.webm`, `abop-1.24-frames.zip`. */
export function movieFileName(name: string, format: MovieFormat): string {
  return format === 'png' ? `${name}-frames.zip` : `${name}.${format}`;
}

/** The name of frame `index` (from 0) of `frames` in a PNG sequence: `abop-1.24-0001.png`, numbered from 1, at least 4 digits. */
export function frameFileName(name: string, index: number, frames: number): string {
  const digits = Math.max(4, String(frames).length);
  return `${name}-${String(index + 1).padStart(digits, '0')}.png`;
}
