import type { WebGLRenderer } from 'three';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { FrameLoop } from './view-renderer';

/** A WebGL 2 context's fences, passed when the test says: `passed` holds the fences the GPU has passed. */
function fakeGpu() {
  let made = 0;
  const passed = new Set<number>();
  const deleted: number[] = [];
  class FakeContext {
    readonly SYNC_GPU_COMMANDS_COMPLETE = 1;
    readonly TIMEOUT_EXPIRED = 2;
    readonly ALREADY_SIGNALED = 3;
    fenceSync(): number {
      return ++made;
    }
    clientWaitSync(sync: number): number {
      return passed.has(sync) ? this.ALREADY_SIGNALED : this.TIMEOUT_EXPIRED;
    }
    deleteSync(sync: number): void {
      deleted.push(sync);
    }
  }
  vi.stubGlobal('WebGL2RenderingContext', FakeContext);
  const gl = new FakeContext();
  return { renderer: { getContext: () => gl } as unknown as WebGLRenderer, passed, deleted, made: () => made };
}

describe('FrameLoop', () => {
  let frames: (() => void)[] = [];
  const nextFrame = () => {
    const due = frames;
    frames = [];
    for (const callback of due) callback();
  };
  beforeEach(() => {
    frames = [];
    vi.stubGlobal('requestAnimationFrame', (callback: () => void) => frames.push(callback));
  });
  afterEach(() => vi.unstubAllGlobals());

  it('draws while one frame is still on the GPU, and waits while two are', () => {
    const gpu = fakeGpu();
    let drawn = 0;
    const loop = new FrameLoop(gpu.renderer, { prepare: () => undefined, render: () => drawn++, after: () => undefined });
    loop.request();
    nextFrame();
    expect(drawn).toBe(1); // fence 1, not passed
    loop.request();
    nextFrame();
    expect(drawn, 'the frame before the last has no fence: drawn').toBe(2); // fences 1 and 2 on the GPU
    loop.request();
    nextFrame();
    expect(drawn, 'fence 1 not passed: waits').toBe(2);
    expect(loop.gpuIdle()).toBe(false);
    gpu.passed.add(1);
    nextFrame();
    expect(drawn, 'fence 1 passed: the third frame').toBe(3);
    expect(gpu.deleted).toEqual([1]);
    expect(loop.gpuIdle(), 'frames 2 and 3 still drawing').toBe(false);
    gpu.passed.add(2);
    gpu.passed.add(3);
    expect(loop.gpuIdle()).toBe(true);
    expect(gpu.deleted).toEqual([1, 3, 2]);
    loop.request();
    nextFrame();
    expect(drawn).toBe(4);
  });

  it('asks for one frame however often asked, and tells its listeners of each frame drawn', () => {
    const gpu = fakeGpu();
    let heard = 0;
    const loop = new FrameLoop(gpu.renderer, { prepare: () => undefined, render: () => undefined, after: () => undefined });
    loop.onRender(() => heard++);
    loop.request();
    loop.request();
    expect(frames).toHaveLength(1);
    nextFrame();
    expect(heard).toBe(1);
    expect(gpu.made()).toBe(1);
  });
});
