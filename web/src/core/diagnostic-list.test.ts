import { describe, expect, it } from 'vitest';
import { columnBuffers, DiagnosticList, diagnosticList, NO_DIAGNOSTICS } from './diagnostic-list';
import type { Diagnostic } from './types';

const diagnostics: Diagnostic[] = [
  { severity: 'error', code: 'E0105', message: 'expected a production', fromByte: 9, toByte: 10, line: 2, column: 1 },
  { severity: 'warning', code: 'E0201', message: "'ω' is set twice: 🌱 wins", fromByte: 4_000_000_000, toByte: 4_000_000_003, line: 100_001, column: 17 },
  { severity: 'error', code: 'E0105', message: '', fromByte: 11, toByte: 11, line: 3, column: 1 },
  { severity: 'error', code: 'E0400', message: 'ünïcödé — “quoted” 𝔽', fromByte: 12, toByte: 20, line: 4, column: 2 },
];

/** `list` as the page gets it from the build worker: its columns cloned with their buffers moved. */
function posted(list: DiagnosticList): DiagnosticList {
  const { columns } = list;
  const buffers = columnBuffers(columns);
  const moved = structuredClone(columns, { transfer: buffers });
  expect(buffers.every((b) => b.byteLength === 0), 'the sender’s buffers are moved, not copied').toBe(true);
  return new DiagnosticList(moved);
}

describe('a list of diagnostics as columns', () => {
  it('gives back every diagnostic as it was, non-ASCII messages and empty ones included, after crossing to the page', () => {
    const list = posted(diagnosticList(diagnostics));
    expect(list).toHaveLength(4);
    expect(list.slice()).toEqual(diagnostics);
    expect([...list]).toEqual(diagnostics);
    expect(list.at(4)).toBeUndefined();
    expect(list.at(-1)).toBeUndefined();
    expect(list.columns.codes).toEqual(['E0105', 'E0201', 'E0400']);
  });

  it('counts, finds and selects without making the others', () => {
    const list = diagnosticList(diagnostics);
    expect(list.count()).toBe(4);
    expect(list.count('error')).toBe(3);
    expect(list.count('warning')).toBe(1);
    expect(list.first('warning')).toEqual(diagnostics[1]);
    expect(list.some((severity, code) => severity === 'warning' && code === 'E0201')).toBe(true);
    expect(list.some((_, code) => code === 'E0999')).toBe(false);
    const errors = list.where((severity, code) => severity === 'error' && code !== 'E0400');
    expect(errors.slice()).toEqual([diagnostics[0], diagnostics[2]]);
    expect(errors.slice(1)).toEqual([diagnostics[2]]);
    expect(list.where(() => true)).toBe(list);
    expect(posted(errors).slice()).toEqual([diagnostics[0], diagnostics[2]]); // (the list's buffers move with it)
  });

  it('of none is empty, on either side', () => {
    for (const list of [NO_DIAGNOSTICS, diagnosticList([]), posted(diagnosticList([]))]) {
      expect(list).toHaveLength(0);
      expect(list.slice()).toEqual([]);
      expect(list.first('error')).toBeUndefined();
      expect(list.count('error')).toBe(0);
    }
  });
});
