// A panic of the core reaches JavaScript as CoreCrashed with the core's own message (not
// WebAssembly's bare "unreachable"). Its own file: a crashed instance is not used again.
import { describe, expect, it } from 'vitest';
import { panicForTests } from '../../crate/pkg/meristem.js';
import { CoreCrashed } from '../../web/src/core';
import { guarded } from '../../web/src/core/init';

describe('a panic of the core', () => {
  it('comes out as CoreCrashed with the panic message and where it happened', () => {
    let caught: unknown;
    try {
      guarded(() => panicForTests('the test asked for it'));
    } catch (error) {
      caught = error;
    }
    expect(caught).toBeInstanceOf(CoreCrashed);
    const message = (caught as CoreCrashed).message;
    expect(message).toMatch(/^the core crashed \(a bug\): panicked at .*wasm\/panic\.rs/);
    expect(message).toContain('the test asked for it');
  });

  it('leaves other errors as they are', () => {
    expect(() => guarded(() => JSON.parse('{'))).toThrow(SyntaxError);
  });
});
