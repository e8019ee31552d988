import { describe, expect, it } from 'vitest';
import type { BuildResult } from '../../../build';
import { diagnosticList } from '../../../core';
import { derivedGrowth, type DerivedStudio } from './derived-growth';

/**
 * A studio whose timeline asks a build for each new time (as `LazyTimeline.deriveAt` does) and
 * whose builds are answered when the test says: each answer ok, or with the error `fails(at)`.
 */
function fakeStudio(span: number | null, fails: (at: number | null) => string | null = () => null) {
  const asked: (number | null)[] = [];
  const waiting: (() => void)[] = [];
  let building: number | null | undefined;
  let last: { at: number | null; ok: boolean; message: string } | undefined;
  let uploading = false;
  const timeline = {
    timedAt: 2 as number | null,
    timedSpan: () => span,
    pose: () => {},
    deriveAt(t: number | null) {
      if (t === timeline.timedAt) return;
      timeline.timedAt = t;
      asked.push(t);
      building = t;
    },
  };
  /** The build under way is delivered. */
  const answer = () => {
    const error = fails(building!);
    last = { at: building!, ok: error === null, message: error ?? '' };
    building = undefined;
    for (const resolve of waiting.splice(0)) resolve();
  };
  const studio: DerivedStudio = {
    timeline,
    preview: {
      answered: () => (building === undefined ? Promise.resolve() : new Promise((resolve) => waiting.push(resolve))),
      get settled() {
        return building === undefined;
      },
      get lastResult() {
        return last && ({ build: { ok: last.ok, diagnostics: diagnosticList(last.ok ? [] : [{ severity: 'error', code: 'E0400', message: last.message, fromByte: 0, toByte: 0, line: 1, column: 1 }]) } } as unknown as BuildResult);
      },
    },
    uploading: () => uploading,
    nextPlantShown: () => new Promise((resolve) => setTimeout(() => ((uploading = false), resolve()), 5)),
  };
  return { studio, timeline, asked, answer, upload: () => (uploading = true) };
}

/** Lets promises settle. */
const tick = () => new Promise((resolve) => setTimeout(resolve, 0));

describe('a movie of a plant derived at t', () => {
  it('is not made for a plant that grows on the GPU', () => {
    expect(derivedGrowth(fakeStudio(null).studio)).toBeNull();
  });

  it('asks the timeline’s build of each frame’s time and waits for it on screen; whole from t = N; back where it was after', async () => {
    const { studio, timeline, asked, answer, upload } = fakeStudio(6);
    const growth = derivedGrowth(studio)!;
    expect(growth.span).toBe(6);
    let shown = false;
    const frame = growth.show(2.5).then(() => (shown = true));
    await tick();
    expect(asked).toEqual([2.5]);
    expect(shown, 'waits for the build').toBe(false);
    upload(); // (the plant is on its way to the GPU when the build is delivered)
    answer();
    await frame;
    expect(shown).toBe(true);
    // The same time again asks nothing; t ≥ N asks for the grammar's own iterations (null).
    await growth.show(2.5);
    const whole = growth.show(6);
    await tick();
    answer();
    await whole;
    expect(asked).toEqual([2.5, null]);
    growth.restore();
    expect(timeline.timedAt, 'the time the studio showed before').toBe(2);
    await growth.show(4);
    expect(asked, 'nothing is asked after the movie').toEqual([2.5, null, 2]);
  });

  it('fails with the build’s problem at the time it failed, never waiting on', async () => {
    const { studio, answer } = fakeStudio(6, (at) => (at !== null && at > 3 ? 'the string would pass #max_modules' : null));
    const growth = derivedGrowth(studio)!;
    const ok = growth.show(1);
    await tick();
    answer();
    await ok;
    const failing = growth.show(3.5);
    await tick();
    answer();
    await expect(failing).rejects.toThrow('the grammar has errors at t = 3.5: the string would pass #max_modules');
  });

  it('asks again when the timeline asked another time meanwhile', async () => {
    const { studio, timeline, asked, answer } = fakeStudio(6);
    const growth = derivedGrowth(studio)!;
    const frame = growth.show(1.5);
    await tick();
    timeline.deriveAt(5); // (a time the timeline wanted before it was paused)
    answer();
    await tick();
    answer();
    await frame;
    expect(asked).toEqual([1.5, 5, 1.5]);
    expect(timeline.timedAt).toBe(1.5);
  });
});
