import { describe, expect, it } from 'vitest';
import { diagnosticList, type Diagnostic } from '../../core';
import { overrideErrors } from './derivation-controls';

const diagnostic = (code: string, message: string, severity: Diagnostic['severity'] = 'error'): Diagnostic => ({ severity, code, message, fromByte: 0, toByte: 0, line: 1, column: 1 });
const limit = diagnostic('E0400', 'step 13 would make a string of 10346712 modules or more, above the limit of 5000000');

describe('the errors of the iterations box', () => {
  it('tells the step and module limits a number in the box hits, with the core’s message', () => {
    expect(overrideErrors(30, 7, diagnosticList([limit]))).toEqual({
      message: "30 iterations, from the Iterations box (the grammar's own: 7), are too many:",
      items: [`E0400: ${limit.message}`],
    });
    expect(overrideErrors(30, 7, diagnosticList([diagnostic('E0202', '30 iterations are more than the step limit 10')]))?.items).toHaveLength(1);
  });

  it('is silent without an override, and about errors of the text itself', () => {
    expect(overrideErrors(undefined, 7, diagnosticList([limit]))).toBeNull();
    expect(overrideErrors(3, 7, diagnosticList([diagnostic('E0109', "'[' is never closed by a ']'"), diagnostic('E0201', 'set twice', 'warning')]))).toBeNull();
  });
});
