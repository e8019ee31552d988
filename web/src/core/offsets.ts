/**
 * Converts a UTF-8 byte offset into `text` (what the Rust core reports) into a UTF-16 code-unit
 * offset (what JavaScript strings and CodeMirror use).
 *
 * An offset inside a multi-byte character maps to the start of that character (the core clamps the
 * same way); an offset past the end maps to `text.length`; a negative one to 0. A lone surrogate
 * counts as 3 bytes, the size of the U+FFFD that replaces it when the text is encoded for the core.
 */
export function byteOffsetToUtf16(text: string, byteOffset: number): number {
  return scanTo(text, 0, 0, byteOffset);
}

/** From unit `index` of `text`, which is at byte `bytes`, on to the unit of `byteOffset`. */
function scanTo(text: string, bytes: number, index: number, byteOffset: number): number {
  while (index < text.length) {
    const codePoint = text.codePointAt(index) as number;
    const width = utf8Width(codePoint);
    if (bytes + width > byteOffset) return index;
    bytes += width;
    index += codePoint > 0xffff ? 2 : 1;
  }
  return text.length;
}

/** Code units between the marks of {@link utf16Offsets}. */
const MARK_EVERY = 256;

/**
 * {@link byteOffsetToUtf16} for many offsets into one `text`: one pass over the text first (none
 * for ASCII, where bytes are units), then each offset from the nearest mark before it, so a
 * grammar of 100,000 productions converts its spans in linear time, not one scan of the whole
 * text per span.
 */
export function utf16Offsets(text: string): (byteOffset: number) => number {
  if (/^[\u0000-\u007f]*$/.test(text)) return (byteOffset) => Math.min(Math.max(0, byteOffset), text.length);
  // marks[k]: [bytes, index] at the first code point boundary at or after unit k * MARK_EVERY.
  const marks: [number, number][] = [];
  let bytes = 0;
  let index = 0;
  while (index < text.length) {
    if (index >= marks.length * MARK_EVERY) marks.push([bytes, index]);
    const codePoint = text.codePointAt(index) as number;
    bytes += utf8Width(codePoint);
    index += codePoint > 0xffff ? 2 : 1;
  }
  return (byteOffset) => {
    // The last mark at or before the offset (binary search), then code point by code point.
    let low = 0;
    let high = marks.length - 1;
    while (low < high) {
      const middle = (low + high + 1) >> 1;
      if (marks[middle][0] <= byteOffset) low = middle;
      else high = middle - 1;
    }
    const [at, i] = marks[low] ?? [0, 0];
    return scanTo(text, at, i, byteOffset);
  };
}

/** Bytes of one code point in UTF-8. */
function utf8Width(codePoint: number): number {
  if (codePoint < 0x80) return 1;
  if (codePoint < 0x800) return 2;
  if (codePoint < 0x10000) return 3;
  return 4;
}
