import { describe, expect, it } from 'vitest';
import { shortModuleText, shortNumber } from './module-text';

describe('numbers in the string panel', () => {
  it('shows at most 6 significant digits', () => {
    const shortened = [
      ['0.016796159999999997', '0.0167962'],
      ['7.069999999999999', '7.07'],
      ['372.0653893904809', '372.065'],
      ['1.1428571428571428', '1.14286'],
      ['-2.498490228009999', '-2.49849'],
      ['1234567.891', '1234570'],
    ];
    for (const [text, short] of shortened) expect(shortNumber(text), text).toBe(short);
  });

  it('leaves short numbers, whole numbers and what is not a finite number as the core wrote them', () => {
    for (const text of ['1', '0.6', '45', '18.95', '5000000', '123456789', '-0', 'NaN', 'inf', '-inf', '', '0.0000001']) {
      expect(shortNumber(text)).toBe(text);
    }
    expect(shortNumber('0.00000012345678')).toBe('1.23457e-7');
  });

  it('shortens each parameter of a module and nothing else', () => {
    const shortened = [
      ['F(0.016796159999999997)', 'F(0.0167962)'],
      ['A(1,0.6868131868131868,7.069999999999999)', 'A(1,0.686813,7.07)'],
      ['F', 'F'],
      ['@Gc', '@Gc'],
      ['?P(0,1.5,0)', '?P(0,1.5,0)'],
    ];
    for (const [text, short] of shortened) expect(shortModuleText(text), text).toBe(short);
  });
});
