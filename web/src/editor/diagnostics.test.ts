import { describe, expect, it } from 'vitest';
import { diagnosticList, type Diagnostic } from '../core';
import { ProblemList } from './problem-list';

function diagnostic(fromByte: number, toByte: number): Diagnostic {
  return { severity: 'error', code: 'E0109', message: "'[' is never closed by a ']'", fromByte, toByte, line: 3, column: 7 };
}

describe('the problems of a text', () => {
  it('turn byte spans into UTF-16 ranges with the code as source', () => {
    // The "[" is byte 23..24 (the seedling is 4 bytes, 2 UTF-16 units).
    const text = '// 🌱\naxiom: X\nX -> F[';
    const problems = ProblemList.of(text, diagnosticList([diagnostic(23, 24)]));
    expect(problems).toHaveLength(1);
    expect(problems.at(0)).toEqual({ from: 21, to: 22, severity: 'error', message: "'[' is never closed by a ']'", source: 'E0109' });
    expect(text.slice(21, 22)).toBe('[');
  });

  it('clamp spans past the end and never invert them', () => {
    const text = 'axiom: X';
    expect(ProblemList.of(text, diagnosticList([diagnostic(40, 12)])).range(0)).toEqual({ from: text.length, to: text.length });
  });
});
