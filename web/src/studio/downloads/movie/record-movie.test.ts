import { describe, expect, it } from 'vitest';
import type { FrameScene } from './frame-scene';
import type { MoviePlan } from './movie-plan';
import type { MovieWriter } from './movie-writer';
import { recordMovie } from './record-movie';

const plan: MoviePlan = { format: 'webm', width: 64, height: 48, fps: 24, timing: { kind: 'duration', seconds: 0.25 }, from: 1, to: 4, turntable: true, frames: 4 };

/** A scene that records its poses, and a writer that records what it is given. */
function fakes() {
  const poses: [number, number][] = [];
  const drawn: string[] = [];
  const log: string[] = [];
  const scene: FrameScene = {
    at: (t, turn) => void poses.push([t, turn]),
    draw: (width, height) => ({ width, height }) as HTMLCanvasElement,
  };
  const writer: MovieWriter = {
    add: async (frame, index) => void drawn.push(`${index}: ${frame.width} × ${frame.height}`),
    finish: async () => (log.push('finish'), new Blob(['movie'])),
    close: () => void log.push('close'),
  };
  return { poses, drawn, log, scene, make: async () => writer };
}

describe('recordMovie', () => {
  it('poses each frame at its growth time and turn, draws it at the size, adds it in order, and finishes', async () => {
    const { poses, drawn, log, scene, make } = fakes();
    const told: string[] = [];
    const recording = recordMovie(plan, scene, 'tree', (done, frames) => told.push(`${done}/${frames}`), make);
    const file = await recording.done;
    expect(await file?.text()).toBe('movie');
    expect(poses.map(([t]) => t)).toEqual([1, 2, 3, 4]);
    expect(poses.map(([, turn]) => turn)).toEqual([0, Math.PI / 2, Math.PI, (3 * Math.PI) / 2]);
    expect(drawn).toEqual(['0: 64 × 48', '1: 64 × 48', '2: 64 × 48', '3: 64 × 48']);
    expect(told).toEqual(['1/4', '2/4', '3/4', '4/4']);
    expect(log).toEqual(['finish']);
  });

  it('cancels at once: the writer is closed, no frame is added after, nothing is finished', async () => {
    const { drawn, log, scene, make } = fakes();
    let recording: ReturnType<typeof recordMovie> | undefined;
    recording = recordMovie({ ...plan, frames: 100 }, scene, 'tree', (done) => done === 2 && recording?.cancel(), make);
    expect(await recording.done).toBeNull();
    expect(drawn).toEqual(['0: 64 × 48', '1: 64 × 48']);
    expect(log).toEqual(['close']);
  });

  it('cancels at once while a frame waits for its scene (a plant derived at t still building), adding nothing after', async () => {
    const { drawn, log, make } = fakes();
    let posed = 0;
    const slow: FrameScene = {
      // The second frame's plant never arrives.
      at: () => (++posed === 2 ? new Promise<void>(() => {}) : undefined),
      draw: (width, height) => ({ width, height }) as HTMLCanvasElement,
    };
    const recording = recordMovie(plan, slow, 'tree', () => {}, make);
    await new Promise((resolve) => setTimeout(resolve, 20));
    expect(posed).toBe(2);
    recording.cancel();
    expect(await recording.done).toBeNull();
    expect(drawn).toEqual(['0: 64 × 48']);
    expect(log).toEqual(['close']);
  });

  it('passes a scene’s failure on (a build at some t failed), closing the writer', async () => {
    const { log, make } = fakes();
    const failing: FrameScene = {
      at: (t) => (t >= 3 ? Promise.reject(new Error('the grammar has errors at t = 3')) : undefined),
      draw: (width, height) => ({ width, height }) as HTMLCanvasElement,
    };
    const recording = recordMovie(plan, failing, 'tree', () => {}, make);
    await expect(recording.done).rejects.toThrow('the grammar has errors at t = 3');
    expect(log).toEqual(['close']);
  });

  it('passes a writer’s failure on, closing it', async () => {
    const { scene, log } = fakes();
    const failing: MovieWriter = { add: async () => Promise.reject(new Error('the video encoder failed: out of memory')), finish: async () => new Blob(), close: () => void log.push('close') };
    const recording = recordMovie(plan, scene, 'tree', () => {}, async () => failing);
    await expect(recording.done).rejects.toThrow('the video encoder failed: out of memory');
    expect(log).toEqual(['close']);
  });
});
