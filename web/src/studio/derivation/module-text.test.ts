import { describe, expect, it } from 'vitest';
import { shortModuleText, shortNumber } from './module-text';

describe('numbers in the string panel', () => {
  it('shows at most 6 significant digits', () => {
    expect(shortNumber('0.016796159999999997')).toBe('0.0167962');
    expect(shortNumber('7.069999999999999')).toBe('7.07');
    expect(shortNumber('372.0653893904809')).toBe('372.065');
    expect(shortNumber('1.1428571428571428')).toBe('1.14286');
    expect(shortNumber('-2.498490228009999')).toBe('-2.49849');
    expect(shortNumber('1234567.891')).toBe('1234570');
  });

  it('leaves short numbers, whole numbers and what is not a finite number as the core wrote them', () => {
    for (const text of ['1', '0.6', '45', '18.95', '5000000', '123456789', '-0', 'NaN', 'inf', '-inf', '', '0.0000001']) {
      expect(shortNumber(text)).toBe(text);
    }
    expect(shortNumber('0.00000012345678')).toBe('1.23457e-7');
  });

  it('shortens each parameter of a module and nothing else', () => {
    expect(shortModuleText('F(0.016796159999999997)')).toBe('F(0.0167962)');
    expect(shortModuleText('A(1,0.6868131868131868,7.069999999999999)')).toBe('A(1,0.686813,7.07)');
    expect(shortModuleText('F')).toBe('F');
    expect(shortModuleText('@Gc')).toBe('@Gc');
    expect(shortModuleText('?P(0,1.5,0)')).toBe('?P(0,1.5,0)');
  });
});
