import { describe, expect, it } from 'vitest';
import { fileSize, pictureSize } from './downloads';

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
