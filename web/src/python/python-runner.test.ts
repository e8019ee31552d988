// The browser's Python path without a browser: Pyodide from node_modules (the same files the site
// serves from pyodide/), the runtime's sources as the worker bundles them (python-package.ts), two
// small models run through `run`, and what they derived made Meristem text by the core's
// importDerived (the import worker's call), then built.
import { loadPyodide, type PyodideAPI } from 'pyodide';
import { beforeAll, describe, expect, it } from 'vitest';
import { buildPlant, importDerived } from '../core';
import { packageSources } from './python-package';
import { installPackage, runModel, type PythonRunRequest } from './python-runner';

let py: PyodideAPI;

beforeAll(async () => {
  py = await loadPyodide({ stdout: () => {}, stderr: () => {} });
  installPackage(py, packageSources());
}, 120_000);

/** Runs `text` as the L-Py file `name`; the parsed result and its JSON. */
function runLpy(name: string, text: string, options: PythonRunRequest['options'] = {}): { json: string; result: Record<string, unknown> } {
  const json = runModel(py, { files: { [name]: text }, main: name, options: { steps: null, seed: 0, ...options } });
  return { json, result: JSON.parse(json) as Record<string, unknown> };
}

describe('the L-system runtime on Pyodide', () => {
  it('bundles the whole package', () => {
    const sources = packageSources();
    expect(Object.keys(sources)).toContain('meristem_lsystem/__init__.py');
    expect(Object.keys(sources)).toContain('meristem_lsystem/run.py');
  });

  it('runs a production whose body is Python, with the model’s derivation length', () => {
    const { result } = runLpy(
      'tree.lpy',
      'def length(order):\n    return 1.0 / (order + 1)\n\nAxiom: A(0)\nderivation length: 3\nproduction:\nA(order):\n    if order < 2:\n        produce F(length(order))[+(30)A(order + 1)]A(order + 1)\n    else:\n        produce F(0.25)\nendlsystem\n',
    );
    expect(result.ok).toBe(true);
    expect(result.steps).toBe(3);
    expect(result.lstring).toBe('F(1.0)[+(30)F(0.5)[+(30)F(0.25)]F(0.25)]F(0.5)[+(30)F(0.25)]F(0.25)');
  });

  it('gives the model’s error at its line, and Python never runs what is not the model', () => {
    const { result } = runLpy('broken.lpy', 'Axiom: A\nderivation length: 1\nproduction:\nA:\n    produce F(undefined_name)\nendlsystem\n');
    expect(result.ok).toBe(false);
    expect(result.error).toMatchObject({ line: 5 });
    expect(String((result.error as { message: string }).message)).toMatch(/undefined_name/);
  });
});

/** The text of a derived run as the import worker makes it, and its plant's segments. */
function derivedPlant(json: string, main: string, files: Record<string, string>): { text: string; notes: string[]; segments: number; ok: boolean } {
  const encoded = Object.entries(files).map(([name, text]) => ({ name, bytes: new TextEncoder().encode(text) }));
  const imported = importDerived(json, main, encoded, 0);
  const build = buildPlant(imported.text);
  return { text: imported.text, notes: imported.notes.map((n) => n.message), segments: build.ok ? build.stats.segments : -1, ok: build.ok };
}

describe('what Python derived, made Meristem text by the core (the studio’s Python path)', () => {
  it('draws a tree whose lengths a Python function computes: 1 + 2 + 4 + 8 segments', () => {
    const tree = 'from math import sqrt\n\ndef length(order):\n    return 1.0 / sqrt(order + 1)\n\nAxiom: A(0)\nderivation length: 4\nproduction:\nA(order):\n    if order < 3:\n        produce F(length(order)) [ +(35) A(order + 1) ] [ -(35) A(order + 1) ]\n    else:\n        produce F(0.3)\nendlsystem\n';
    const { json, result } = runLpy('tree.lpy', tree);
    expect(result.ok).toBe(true);
    const plant = derivedPlant(json, 'tree.lpy', { 'tree.lpy': tree });
    expect(plant.ok).toBe(true);
    expect(plant.segments).toBe(1 + 2 + 4 + 8);
    expect(plant.text).toMatch(/Python/);
  });

  it('draws a model whose string Start and EndEach change through globals, seeded', () => {
    const model = 'import random\n\ndef Start():\n    global grown\n    grown = 0\n\ndef EndEach():\n    global grown\n    grown += 1\n\nAxiom: A\nderivation length: 6\nproduction:\nA:\n    if random.random() < 2 and grown < 5:\n        produce F A\n    else:\n        produce F\nendlsystem\n';
    const { json, result } = runLpy('globals.lpy', model, { seed: 3 });
    expect(result.ok).toBe(true);
    expect(String(result.lstring).replace(/ /g, '')).toBe('FFFFFF');
    expect(derivedPlant(json, 'globals.lpy', { 'globals.lpy': model }).segments).toBe(6);
  });
});
