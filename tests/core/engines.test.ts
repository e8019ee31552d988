// Every installed package runs on the Node the project promises: package.json's `engines.node`
// (README: "Node.js ≥ 20.19"). A dependency whose own `engines.node` leaves out the oldest Node of
// that range (as @axe-core/playwright 4.14's ">=22.12" did) fails here with its name and range, so
// a version bump that drops the promised Node is caught before a user on it meets it.
import { existsSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import semver from 'semver';
import { describe, expect, it } from 'vitest';

const root = new URL('../../', import.meta.url).pathname;

interface Manifest {
  name?: string;
  version?: string;
  engines?: { node?: string };
}

function read<T>(path: string): T {
  return JSON.parse(readFileSync(join(root, path), 'utf8')) as T;
}

const promised = read<Manifest>('package.json').engines?.node ?? '';
const oldest = semver.minVersion(promised)?.version ?? '';

/** The Node ranges that leave out `version`: "name@version: range" for each installed package the lockfile lists. */
function excluding(version: string): string[] {
  const lock = read<{ packages: Record<string, { link?: boolean }> }>('package-lock.json');
  return Object.entries(lock.packages)
    .filter(([path, entry]) => path.includes('node_modules/') && !entry.link)
    .map(([path]) => join(path, 'package.json'))
    // Optional packages for other platforms are listed but not installed.
    .filter((path) => existsSync(join(root, path)))
    .map((path) => read<Manifest>(path))
    .filter((manifest) => manifest.engines?.node !== undefined && !allows(manifest.engines.node, version))
    .map((manifest) => `${manifest.name}@${manifest.version}: node ${manifest.engines?.node}`);
}

/** Whether an `engines.node` range admits the version; a range semver cannot read does not. */
function allows(range: string, version: string): boolean {
  return semver.validRange(range) !== null && semver.satisfies(version, range, { includePrerelease: true });
}

describe('the Node version the project promises', () => {
  it('is the one the README names', () => {
    expect(promised).toBe('>=20.19');
    const readme = readFileSync(join(root, 'README.md'), 'utf8');
    expect(readme).toContain(`Node.js ≥ ${promised.replace('>=', '')}`);
  });

  it('is supported by every installed package', () => {
    expect(oldest).toBe('20.19.0');
    expect(excluding(oldest)).toEqual([]);
  });

  it('tells a range that leaves it out', () => {
    expect(allows('>=22.12', oldest)).toBe(false);
    expect(allows('^20.19.0 || ^22.13.0 || >=24', oldest)).toBe(true);
    expect(allows('>= 14', oldest)).toBe(true);
    expect(allows('not a range', oldest)).toBe(false);
  });
});
