import { describe, expect, it } from 'vitest';
import type { Diagnostic } from '../core';
import { toEditorDiagnostics } from './diagnostics';

function diagnostic(fromByte: number, toByte: number): Diagnostic {
  return { severity: 'error', code: 'E0109', message: "'[' is never closed by a ']'", fromByte, toByte, line: 3, column: 7 };
}

describe('toEditorDiagnostics', () => {
  it('turns byte spans into UTF-16 ranges with the code as source', () => {
    // The "[" is byte 23..24 (the seedling is 4 bytes, 2 UTF-16 units).
    const text = '// 🌱\naxiom: X\nX -> F[';
    expect(toEditorDiagnostics(text, [diagnostic(23, 24)])).toEqual([
      { from: 21, to: 22, severity: 'error', message: "'[' is never closed by a ']'", source: 'E0109' },
    ]);
    expect(text.slice(21, 22)).toBe('[');
  });

  it('clamps spans past the end and never inverts them', () => {
    const text = 'axiom: X';
    const [d] = toEditorDiagnostics(text, [diagnostic(40, 12)]);
    expect(d).toMatchObject({ from: text.length, to: text.length });
  });
});
