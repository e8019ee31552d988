import { describe, expect, it } from 'vitest';
import { frameCount, frameFileName, frameTime, frameTurn, movieFileName, planMovie, type MovieOptions } from './movie-plan';

const webm: MovieOptions = { format: 'webm', width: 1280, height: 720, fps: 30, timing: { kind: 'duration', seconds: 10 }, from: 0, to: 7, turntable: false };

describe('the frames of a movie', () => {
  it('counts fps × seconds, or fps × seconds per step × steps', () => {
    expect(frameCount(webm)).toBe(300);
    expect(frameCount({ ...webm, timing: { kind: 'per-step', seconds: 0.5 } })).toBe(105); // 7 steps × 0.5 s × 30
    expect(frameCount({ ...webm, from: 2, to: 5, timing: { kind: 'per-step', seconds: 1 } })).toBe(90);
    expect(frameCount({ ...webm, fps: 24, timing: { kind: 'duration', seconds: 0.01 } })).toBe(1);
  });

  it('spans the time range from its first frame to its last, evenly', () => {
    const times = Array.from({ length: 8 }, (_, i) => frameTime(i, 8, 0, 7));
    expect(times).toEqual([0, 1, 2, 3, 4, 5, 6, 7]);
    expect(frameTime(0, 5, 2, 4)).toBe(2);
    expect(frameTime(2, 5, 2, 4)).toBe(3);
    expect(frameTime(4, 5, 2, 4)).toBe(4);
    expect(frameTime(0, 1, 0, 7), 'a single frame shows the whole plant of the range').toBe(7);
  });

  it('turns once over the movie, the last frame a frame short of a whole turn (loops smoothly)', () => {
    expect(frameTurn(0, 4, true)).toBe(0);
    expect(frameTurn(1, 4, true)).toBeCloseTo(Math.PI / 2);
    expect(frameTurn(3, 4, true)).toBeCloseTo((3 * Math.PI) / 2);
    expect(frameTurn(3, 4, false)).toBe(0);
  });
});

describe('the choices checked', () => {
  it('plans a movie of good choices', () => {
    const planned = planMovie(webm, 7);
    expect(planned).toEqual({ ok: true, plan: { ...webm, frames: 300 } });
  });

  it('refuses sizes out of range or odd for a video, naming the range', () => {
    for (const [width, height] of [
      [15, 720],
      [1280.5, 720],
      [NaN, 720],
      [3842, 720],
    ]) {
      const planned = planMovie({ ...webm, width, height }, 7);
      expect(planned.ok, `${width} × ${height}`).toBe(false);
      if (!planned.ok) expect(planned.message).toContain('from 16 to 3840 for a WebM video');
    }
    const odd = planMovie({ ...webm, width: 641, height: 360 }, 7);
    expect(odd).toEqual({ ok: false, message: 'Size: a video’s width and height must be even numbers' });
    expect(planMovie({ ...webm, format: 'gif', width: 641, height: 361, fps: 10 }, 7).ok, 'a GIF may be odd').toBe(true);
    const gpu = planMovie(webm, 7, 1024);
    expect(gpu.ok === false && gpu.message).toContain('from 16 to 1024');
  });

  it('refuses frame rates the format cannot keep', () => {
    const gif = planMovie({ ...webm, format: 'gif', width: 320, height: 240, fps: 30 }, 7);
    expect(gif).toEqual({ ok: false, message: 'Frame rate: an animated GIF is written at 10, 20, 25 frames a second' });
  });

  it('refuses durations and ranges that are not numbers in range', () => {
    expect(planMovie({ ...webm, timing: { kind: 'duration', seconds: 0 } }, 7)).toEqual({ ok: false, message: 'Duration: give a number of seconds above 0' });
    expect(planMovie({ ...webm, timing: { kind: 'per-step', seconds: NaN } }, 7)).toEqual({ ok: false, message: 'Seconds per step: give a number above 0' });
    for (const [from, to] of [
      [-1, 7],
      [0, 8],
      [5, 4],
      [NaN, 7],
    ]) {
      const planned = planMovie({ ...webm, from, to }, 7);
      expect(planned, `${from}…${to}`).toEqual({ ok: false, message: 'Time range: from and to must be steps between 0 and 7, from not after to' });
    }
  });

  it('refuses seconds per step over a range of no steps, but films a still plant for seconds in all', () => {
    expect(planMovie({ ...webm, from: 3, to: 3, timing: { kind: 'per-step', seconds: 1 } }, 7)).toEqual({
      ok: false,
      message: 'Time range: from and to are the same step; give a range, or the length in seconds in all',
    });
    expect(planMovie({ ...webm, from: 3, to: 3, turntable: true }, 7).ok).toBe(true);
  });

  it('makes a plant without growth times a movie of the seconds given, its range ignored', () => {
    const planned = planMovie({ ...webm, turntable: true, timing: { kind: 'per-step', seconds: 2 }, from: 3, to: 99 }, null);
    expect(planned.ok && planned.plan).toMatchObject({ from: 0, to: 0, frames: 60, timing: { kind: 'duration', seconds: 2 } });
  });

  it('limits the frames, and the pixels of all frames together, saying how to fit', () => {
    const long = planMovie({ ...webm, timing: { kind: 'duration', seconds: 601 } }, 7);
    expect(long).toEqual({ ok: false, message: 'That is 18,030 frames; a movie has at most 18,000: make it shorter or slower' });
    const gif = planMovie({ ...webm, format: 'gif', fps: 25, timing: { kind: 'duration', seconds: 12 } }, 7);
    expect(gif).toEqual({
      ok: false,
      message: 'An animated GIF of 300 frames at 1280 × 720 is 276.5 million pixels; the most is 60 million: make it smaller (about 46% of this size) or shorter',
    });
    expect(planMovie({ ...webm, format: 'gif', width: 588, height: 330, fps: 25, timing: { kind: 'duration', seconds: 12 } }, 7).ok, 'at 46%').toBe(true);
  });
});

describe('file names', () => {
  it('names the movie after the grammar', () => {
    expect(movieFileName('abop-1.24', 'webm')).toBe('abop-1.24.webm');
    expect(movieFileName('abop-1.24', 'mp4')).toBe('abop-1.24.mp4');
    expect(movieFileName('abop-1.24', 'gif')).toBe('abop-1.24.gif');
    expect(movieFileName('abop-1.24', 'png')).toBe('abop-1.24-frames.zip');
  });

  it('numbers the PNGs from 1, with as many digits as the last needs (at least four), so they sort', () => {
    expect(frameFileName('tree', 0, 300)).toBe('tree-0001.png');
    expect(frameFileName('tree', 299, 300)).toBe('tree-0300.png');
    expect(frameFileName('tree', 0, 18000)).toBe('tree-00001.png');
  });
});
