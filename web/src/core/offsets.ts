/**
 * Converts a UTF-8 byte offset into `text` (what the Rust core reports) into a UTF-16 code-unit
 * offset (what JavaScript strings and CodeMirror use).
 *
 * An offset inside a multi-byte character maps to the start of that character (the core clamps the
 * same way); an offset past the end maps to `text.length`; a negative one to 0. A lone surrogate
 * counts as 3 bytes, the size of the U+FFFD that replaces it when the text is encoded for the core.
 */
export function byteOffsetToUtf16(text: string, byteOffset: number): number {
  let bytes = 0;
  let index = 0;
  while (index < text.length) {
    const codePoint = text.codePointAt(index) as number;
    const width = utf8Width(codePoint);
    if (bytes + width > byteOffset) return index;
    bytes += width;
    index += codePoint > 0xffff ? 2 : 1;
  }
  return text.length;
}

/** Bytes of one code point in UTF-8. */
function utf8Width(codePoint: number): number {
  if (codePoint < 0x80) return 1;
  if (codePoint < 0x800) return 2;
  if (codePoint < 0x10000) return 3;
  return 4;
}
