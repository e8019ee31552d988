import { describe, expect, it } from 'vitest';
import { byteOffsetToUtf16, utf16Offsets } from './offsets';

/** Every char boundary of `text` as [utf8 byte offset, utf16 offset], computed with TextEncoder. */
function boundaries(text: string): [number, number][] {
  const result: [number, number][] = [[0, 0]];
  let bytes = 0;
  let units = 0;
  for (const char of text) {
    bytes += new TextEncoder().encode(char).length;
    units += char.length;
    result.push([bytes, units]);
  }
  return result;
}

describe('byteOffsetToUtf16', () => {
  it('is the identity on ASCII', () => {
    const text = 'axiom: X\nX -> F[+X]';
    for (let i = 0; i <= text.length; i++) expect(byteOffsetToUtf16(text, i)).toBe(i);
  });

  // [what, text, [utf8 byte offset, utf16 offset] pairs]
  it.each<[string, string, [number, number][]]>([
    // "é" is 2 bytes in UTF-8, 1 UTF-16 unit.
    ['counts 2-byte characters as one unit', 'é->F', [[0, 0], [2, 1], [4, 3], [5, 4]]],
    // "→" (U+2192, the arrow the grammar accepts) is 3 bytes, 1 unit.
    ['counts 3-byte characters as one unit', 'X → FX', [[2, 2], [5, 3], [6, 4], [8, 6]]],
    // "🌱" (U+1F331) is 4 bytes in UTF-8 and a surrogate pair in UTF-16; the last pair is the final F.
    ['counts 4-byte (astral) characters as two units', '// 🌱 sprout\nF', [[3, 3], [7, 5], [8, 6], [15, 13]]],
    ['maps an offset inside a character to the start of that character', 'a🌱b', [[2, 1], [3, 1], [4, 1], [5, 3]]],
  ])('%s', (_, text, pairs) => {
    expect(pairs.map(([bytes]) => byteOffsetToUtf16(text, bytes))).toEqual(pairs.map(([, units]) => units));
  });

  it('maps offsets at and past the end to the length', () => {
    const text = 'F→🌱é';
    const end = new TextEncoder().encode(text).length;
    expect(end).toBe(10);
    expect(byteOffsetToUtf16(text, end)).toBe(text.length);
    expect(byteOffsetToUtf16(text, end + 1)).toBe(text.length);
    expect(byteOffsetToUtf16(text, Number.MAX_SAFE_INTEGER)).toBe(text.length);
    expect(byteOffsetToUtf16('', 0)).toBe(0);
    expect(byteOffsetToUtf16('', 3)).toBe(0);
  });

  it('maps negative offsets to 0', () => {
    expect(byteOffsetToUtf16('abc', -1)).toBe(0);
  });

  it('agrees with TextEncoder at every boundary of mixed text', () => {
    const text = 'p1: X → F[+X]é中🌿𝒳\n// ok';
    const slices = boundaries(text);
    for (const [bytes, units] of slices) expect(byteOffsetToUtf16(text, bytes)).toBe(units);
  });
});

describe('utf16Offsets', () => {
  it('agrees with byteOffsetToUtf16 at every byte of mixed text, in any order', () => {
    const text = ('axiom: ωF é 😀 X\n'.repeat(60) + 'A -> B\n').repeat(3);
    const convert = utf16Offsets(text);
    const total = new TextEncoder().encode(text).length;
    const offsets = [...Array(total + 3).keys()].map((i) => i - 1).reverse();
    for (const b of offsets) expect(convert(b), `byte ${b}`).toBe(byteOffsetToUtf16(text, b));
  });

  it('is the identity (clamped) on ASCII', () => {
    const convert = utf16Offsets('axiom: F');
    expect([convert(-1), convert(0), convert(5), convert(8), convert(99)]).toEqual([0, 0, 5, 8, 8]);
  });
});
