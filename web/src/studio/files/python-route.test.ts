import { zipSync } from 'fflate';
import { describe, expect, it } from 'vitest';
import { openObjectBytes } from './grammar-files';
import { pythonRequest, unpacked } from './python-route';

const encode = (text: string) => new TextEncoder().encode(text);

/** What the import worker answers for `files`: the Python request, or null for the hand translation. */
function route(files: { name: string; bytes: Uint8Array }[]) {
  return pythonRequest(files, openObjectBytes(files));
}

// A Python function with a loop: the hand translation cannot carry it (`from math import …` alone
// would not need Python: its names are translated).
const BODY = 'def length(n):\n    s = 1\n    for i in range(n):\n        s += i\n    return s\n\nAxiom: A(0)\nderivation length: 2\nproduction:\nA(n):\n    if n < 1:\n        produce F(length(n + 2))[+A(n + 1)]A(n + 1)\n    else:\n        produce F\nendlsystem\n';
const LPFG = '#include <lpfgall.h>\nmodule A(int);\nderivation length: 2;\nAxiom: A(0);\nA(n) :\n{\n  if (n < 2) produce F(1) A(n + 1);\n}\n';

describe('the Python route of opened files', () => {
  it('runs an L-Py model whose Python the translation cannot carry, with its text', () => {
    const request = route([{ name: 'tree.lpy', bytes: encode(BODY) }]);
    expect(request).toEqual({ files: { 'tree.lpy': BODY }, main: 'tree.lpy', options: { dialect: 'lpy', steps: null, seed: 0 } });
  });

  it('keeps the hand translation of a model it translates whole, and never runs cpfg or Meristem text', () => {
    expect(route([{ name: 'plain.lpy', bytes: encode('Axiom: F\nderivation length: 2\nproduction:\nF --> F[+F]F\nendlsystem\n') }])).toBeNull();
    expect(route([{ name: 'plant.l', bytes: encode('#define N 2\nLsystem: 1\nderivation length: N\nAxiom: F\nF --> F[+F]F\nendlsystem\n') }])).toBeNull();
  });

  it('unpacks a zipped lpfg object for Python, its binary files left out', () => {
    const zip = zipSync({ 'object/plant.l': encode(LPFG), 'object/specifications': encode('lpfg plant.l\n'), 'object/texture.rgb': new Uint8Array([1, 0, 2]) });
    const request = route([{ name: 'object.zip', bytes: zip }]);
    expect(request?.main).toBe('object/plant.l');
    expect(request?.options.dialect).toBe('lpfg');
    expect(Object.keys(request?.files ?? {}).sort()).toEqual(['object/plant.l', 'object/specifications']);
    expect(unpacked([{ name: 'broken.zip', bytes: encode('not a zip') }])).toBeNull();
  });
});
