// What the export tests share: the command-line tool (built once, release), the gallery, a
// scratch folder, and the real consumers run as processes. A missing consumer is a failure that
// names the command installing it, never a skip.
import { execFileSync, spawnSync } from 'node:child_process';
import { copyFileSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

export const repoRoot = fileURLToPath(new URL('../..', import.meta.url));
export const galleryDir = join(repoRoot, 'public/examples');
export const goldenDir = join(repoRoot, 'crate/tests/golden/export');

/** `npm test` installs these (scripts/setup.sh, as root) or prints this command. */
export const INSTALL_CONSUMERS = 'sudo apt-get install -y povray view3dscene xvfb xauth inventor-clients';

let binary: string | undefined;

/** The `meristem` binary, built (release) on first use. */
export function meristem(): string {
  if (!binary) {
    execFileSync('cargo', ['build', '--quiet', '--release', '--manifest-path', 'crate/Cargo.toml', '--bin', 'meristem'], {
      cwd: repoRoot,
      stdio: 'inherit',
    });
    binary = join(repoRoot, 'crate/target/release/meristem');
  }
  return binary;
}

/** Every gallery grammar, by file name (sorted). */
export function galleryExamples(): string[] {
  return readdirSync(galleryDir)
    .filter((name) => name.endsWith('.lsys'))
    .sort();
}

/** The golden grammars' names without extension (`leafy-3d`, …). */
export function goldenNames(): string[] {
  return readdirSync(goldenDir)
    .filter((name) => name.endsWith('.lsys'))
    .map((name) => name.slice(0, -'.lsys'.length))
    .sort();
}

/**
 * A fresh scratch folder under the system's temp dir (POV-Ray may read and write there); remove it
 * with {@link removeScratch} when the file's tests are done: exports of the large examples take
 * hundreds of megabytes.
 */
export function scratchDir(label: string): string {
  return mkdtempSync(join(tmpdir(), `meristem-${label}-`));
}

/** Deletes a folder made by {@link scratchDir}. */
export function removeScratch(dir: string): void {
  rmSync(dir, { recursive: true, force: true });
}

/** Keeps a rendered picture in test-results/export/ for a person to look at. */
export function keepPicture(png: string, name: string): void {
  const results = join(repoRoot, 'test-results/export');
  mkdirSync(results, { recursive: true });
  copyFileSync(png, join(results, name));
}

/** Runs `meristem export GRAMMAR -o OUT ...extra` and returns the written file's bytes. */
export function exportWithCli(grammar: string, out: string, extra: string[] = []): Buffer {
  execFileSync(meristem(), ['export', grammar, '-o', out, ...extra], { stdio: ['ignore', 'ignore', 'inherit'] });
  return readFileSync(out);
}

/** `derive --stats` of a grammar: the counts the exports must hold. */
export interface CliStats {
  segments: number;
  vertices: number;
  triangles: number;
  lines: number;
}

export function statsOf(grammar: string): CliStats {
  return JSON.parse(execFileSync(meristem(), ['derive', grammar, '--stats'], { encoding: 'utf8' })) as CliStats;
}

/** Throws a clear error when a consumer program is not installed. */
export function requireTool(program: string): void {
  const found = spawnSync('sh', ['-c', `command -v ${program}`], { encoding: 'utf8' });
  if (found.status !== 0) {
    throw new Error(`${program} is not installed; the export tests run the real consumers. Install them with: ${INSTALL_CONSUMERS}`);
  }
}

/** Output of a consumer run: exit status and both streams. */
export interface ToolRun {
  status: number | null;
  stdout: string;
  stderr: string;
}

/** Runs a consumer program (after {@link requireTool}); stdout is kept unless `discardStdout`. */
export function runTool(program: string, args: string[], options: { cwd?: string; discardStdout?: boolean } = {}): ToolRun {
  requireTool(program);
  const run = spawnSync(program, args, {
    cwd: options.cwd ?? repoRoot,
    encoding: 'utf8',
    timeout: 300_000,
    maxBuffer: 1 << 26,
    stdio: ['ignore', options.discardStdout ? 'ignore' : 'pipe', 'pipe'],
  });
  if (run.error) throw run.error;
  return { status: run.status, stdout: run.stdout ?? '', stderr: run.stderr ?? '' };
}
