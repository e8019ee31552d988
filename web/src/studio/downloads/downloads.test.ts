import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import { fileSize, paperPixels, pictureSize, withResolution } from './downloads';

describe('downloads', () => {
  it('reads a PNG size from the inputs', () => {
    expect(pictureSize('1600', ' 1200 ')).toEqual({ ok: true, width: 1600, height: 1200 });
    expect(pictureSize('16', '8192')).toEqual({ ok: true, width: 16, height: 8192 });
  });

  it('refuses sizes that are not whole numbers in range, naming the range', () => {
    for (const [w, h] of [
      ['', '100'],
      ['100.5', '100'],
      ['15', '100'],
      ['100', '8193'],
      ['abc', '100'],
      ['100', '-1'],
    ]) {
      const size = pictureSize(w, h);
      expect(size.ok, `${w} × ${h}`).toBe(false);
      if (!size.ok) expect(size.message).toContain('from 16 to 8192');
    }
    expect(pictureSize('5000', '100', 4096)).toEqual({
      ok: false,
      message: 'PNG size: width and height must be whole numbers from 16 to 4096',
    });
  });

  it('words file sizes', () => {
    expect(fileSize(1)).toBe('1 byte');
    expect(fileSize(812)).toBe('812 bytes');
    expect(fileSize(14_200)).toBe('14.2 KB');
    expect(fileSize(3_456_789)).toBe('3.5 MB');
    expect(fileSize(2e9)).toBe('2 GB');
  });
});

describe('pictures for print', () => {
  it('sizes a sheet of paper in pixels at a resolution', () => {
    expect(paperPixels('a5-portrait', 300)).toEqual({ width: 1748, height: 2480 });
    expect(paperPixels('a5-landscape', 300)).toEqual({ width: 2480, height: 1748 });
    expect(paperPixels('a4-portrait', 72)).toEqual({ width: 595, height: 842 });
  });

  it('records the resolution in the PNG (pHYs after the header), once, with a valid checksum', () => {
    const png = new PNG({ width: 3, height: 2 });
    png.data.fill(255);
    const bytes = new Uint8Array(PNG.sync.write(png));
    const at300 = withResolution(withResolution(bytes, 150), 300);
    const text = String.fromCharCode(...at300);
    expect(text.indexOf('pHYs')).toBe(8 + 25 + 4); // signature, IHDR chunk, then pHYs's length
    expect(text.indexOf('pHYs', text.indexOf('pHYs') + 1), 'one pHYs only').toBe(-1);
    const data = new DataView(at300.buffer, text.indexOf('pHYs') + 4);
    expect([data.getUint32(0), data.getUint32(4), data.getUint8(8)]).toEqual([11811, 11811, 1]); // 300 DPI in dots per metre
    // pngjs checks every chunk's CRC while decoding.
    const decoded = PNG.sync.read(Buffer.from(at300));
    expect([decoded.width, decoded.height]).toEqual([3, 2]);
  });
});
