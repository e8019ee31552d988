import { describe, expect, it } from 'vitest';
import { diagnosticList, NO_DIAGNOSTICS, type Diagnostic, type PlantStats } from '../../core';
import { plural, reportBuilding, reportErrors, reportPlant } from './status';

const stats: PlantStats = {
  modules: 12345,
  segments: 1,
  vertices: 1024,
  triangles: 2000,
  lines: 0,
  iterations: 7,
  bounds: [
    [0, 0, 0],
    [1, 1, 1],
  ],
};

function diagnostic(severity: Diagnostic['severity']): Diagnostic {
  return { severity, code: 'E0000', message: 'm', fromByte: 0, toByte: 1, line: 1, column: 1 };
}

describe('status line', () => {
  it('pluralises', () => {
    expect(plural(1, 'error')).toBe('1 error');
    expect(plural(0, 'error')).toBe('0 errors');
    expect(plural(1500, 'module')).toBe('1,500 modules');
  });

  const timings = { parseResolve: 0.04, derive: 1.25, interpret: 12.5, mesh: 61.3 };

  it('reports the sizes, the time of each stage and the whole round trip', () => {
    expect(reportPlant(stats, NO_DIAGNOSTICS, timings, 83.14159)).toEqual({
      state: 'ok',
      text:
        '12,345 modules · 1 segment · 1,024 vertices · 2,000 triangles · ' +
        'parse+resolve 0.0 · derive 1.3 · interpret 13 · mesh 61 ms · 83 ms round trip',
    });
    expect(reportPlant(stats, diagnosticList([diagnostic('warning')]), timings, 4.24).text).toMatch(/· 4\.2 ms round trip · 1 warning$/);
  });

  it('says "drawn as lines" for a plant with segments and no mesh (the Lines mode), not "0 vertices"', () => {
    const lines = { ...stats, vertices: 0, triangles: 0, lines: 0 };
    expect(reportPlant(lines, NO_DIAGNOSTICS, timings, 9).text).toMatch(/^12,345 modules · 1 segment · drawn as lines · parse\+resolve /);
    const empty = { ...stats, segments: 0, vertices: 0, triangles: 0, lines: 0 };
    expect(reportPlant(empty, NO_DIAGNOSTICS, timings, 9).text).toMatch(/· 0 segments · 0 vertices · 0 triangles ·/);
  });

  it('says when a model too large to mesh is drawn as lines', () => {
    const huge = { ...stats, vertices: 0, triangles: 0, lines: 2000000 };
    expect(reportPlant(huge, NO_DIAGNOSTICS, timings, 900).text).toMatch(/· too large to mesh: 2,000,000 segments drawn as lines$/);
  });

  it('reports errors, whether the last good plant is still shown, and the first error in words', () => {
    const twoErrors = [diagnostic('warning'), diagnostic('error'), diagnostic('error')];
    twoErrors[1] = { ...twoErrors[1], line: 3, message: 'the derivation needs 9 GiB; lower #max_modules' };
    expect(reportErrors(diagnosticList(twoErrors), true)).toEqual({
      state: 'stale',
      text: '2 errors — showing last good plant · line 3: the derivation needs 9 GiB; lower #max_modules',
    });
    expect(reportErrors(diagnosticList([diagnostic('error')]), false)).toEqual({ state: 'error', text: '1 error — no plant yet · line 1: m' });
  });

  it('says what a build is doing, never a plant’s figures', () => {
    expect(reportBuilding(undefined, 300)).toEqual({ state: 'building', text: 'Building…' });
    expect(reportBuilding({ stage: 'parsing', step: 0, steps: 0 }, 400).text).toBe('Building… reading the grammar');
    expect(reportBuilding({ stage: 'deriving', step: 0, steps: 0 }, 400).text).toBe('Building… deriving');
    expect(reportBuilding({ stage: 'deriving', step: 1234, steps: 5000 }, 2500).text).toBe('Building… step 1,234 of 5,000 · 2 s');
    expect(reportBuilding({ stage: 'meshing', step: 0, steps: 0 }, 61_000).text).toBe('Building… meshing · 61 s');
    // The environment answering between steps says so, with the step whose plant it answers.
    expect(reportBuilding({ stage: 'environment', step: 12, steps: 40 }, 3200).text).toBe('Building… environment, step 12 of 40 · 3 s');
    expect(reportBuilding({ stage: 'environment', step: 0, steps: 0 }, 400).text).toBe('Building… environment');
  });
});
