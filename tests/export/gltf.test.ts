// glTF: every gallery example, the golden grammars and an empty plant, exported as GLB by the
// command-line tool, pass the Khronos glTF validator with no error and no warning, and hold the
// plant's triangles.
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { validateBytes, type ValidationReport } from 'gltf-validator';
import { afterAll, describe, expect, it } from 'vitest';
import { exportWithCli, galleryDir, galleryExamples, goldenDir, goldenNames, removeScratch, scratchDir, statsOf } from './tools';

const dir = scratchDir('gltf');
afterAll(() => removeScratch(dir));

async function validate(bytes: Uint8Array, uri: string): Promise<ValidationReport> {
  return validateBytes(bytes, { uri, maxIssues: 20 });
}

function problems(report: ValidationReport): string {
  return report.issues.messages.map((m) => `${m.code} ${m.pointer ?? ''}: ${m.message}`).join('\n');
}

describe('GLB from the command-line tool, checked by the Khronos glTF validator', () => {
  it.each(galleryExamples())('%s: 0 errors, 0 warnings, every triangle', async (name) => {
    const grammar = join(galleryDir, name);
    const bytes = exportWithCli(grammar, join(dir, `${name}.glb`));
    const report = await validate(new Uint8Array(bytes), `${name}.glb`);
    expect(report.issues.numErrors, problems(report)).toBe(0);
    expect(report.issues.numWarnings, problems(report)).toBe(0);
    const stats = statsOf(grammar);
    expect(report.info?.totalTriangleCount).toBe(stats.triangles);
  });

  it.each(goldenNames())('golden %s.glb: 0 errors, 0 warnings', async (name) => {
    const report = await validate(new Uint8Array(readFileSync(join(goldenDir, `${name}.glb`))), `${name}.glb`);
    expect(report.issues.numErrors, problems(report)).toBe(0);
    expect(report.issues.numWarnings, problems(report)).toBe(0);
  });

  it('a plant that draws nothing is an empty but valid scene', async () => {
    const grammar = join(dir, 'empty.lsys');
    writeFileSync(grammar, 'axiom: X\n');
    const report = await validate(new Uint8Array(exportWithCli(grammar, join(dir, 'empty.glb'))), 'empty.glb');
    expect(report.issues.numErrors, problems(report)).toBe(0);
    expect(report.issues.numWarnings, problems(report)).toBe(0);
  });

  it('the validator does catch a broken file (the check can fail)', async () => {
    const bytes = readFileSync(join(goldenDir, 'leafy-3d.glb'));
    const report = await validate(new Uint8Array(bytes.subarray(0, bytes.length - 8)), 'truncated.glb');
    expect(report.issues.numErrors).toBeGreaterThan(0);
  });
});
