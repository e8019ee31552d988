import { describe, expect, it } from 'vitest';
import { addressRequest, assignmentLink, assignmentUrl, fingerprint, submissionLink, unpackAssignment, unpackSubmission, type Submission } from './assignment-links';
import { packText } from '../../share/codec';

const STUDIO = { origin: 'https://studio.example', pathname: '/meristem/' };
const WORK: Submission = { url: 'https://course.example/a1.md', fingerprint: '0123456789abcdef', title: 'A1', grammar: 'axiom: F\n// </script><img src=x onerror=alert(1)>\n', name: 'Ada' };

describe('assignment and submission links', () => {
  it('read the address: a URL, a packed assignment, a submission, or none', () => {
    expect(addressRequest({ search: '?assignment=https%3A%2F%2Fcourse.example%2Fa1.md', hash: '' })).toEqual({ kind: 'url', url: 'https://course.example/a1.md' });
    expect(addressRequest({ search: '', hash: '#assignment=1.abc_-' })).toEqual({ kind: 'packed', packed: '1.abc_-' });
    expect(addressRequest({ search: '?x=1', hash: '#submission=1.abc' })).toEqual({ kind: 'submission', packed: '1.abc' });
    expect(addressRequest({ search: '', hash: '#s=1.abc' })).toEqual({ kind: 'none' });
    expect(addressRequest({ search: '', hash: '#submission=1.a<b' })).toEqual({ kind: 'none' });
  });

  it('fetch assignments only over http and https, and not http from an https studio', () => {
    expect(assignmentUrl('a1.md', 'https://course.example/x/')).toEqual({ ok: true, url: 'https://course.example/x/a1.md' });
    expect(assignmentUrl('javascript:alert(1)', 'https://s.example/')).toMatchObject({ ok: false, error: expect.stringContaining('not javascript:') });
    expect(assignmentUrl('http://course.example/a1.md', 'https://s.example/')).toMatchObject({ ok: false, error: expect.stringContaining('https') });
    expect(assignmentUrl(`https://a.example/${'x'.repeat(3000)}`, 'https://s.example/').ok).toBe(false);
  });

  it('fingerprint a text whatever its line ends, and tell one character apart', () => {
    expect(fingerprint('a\r\nb')).toBe(fingerprint('a\nb'));
    expect(fingerprint('a\nb')).toMatch(/^[0-9a-f]{16}$/);
    expect(fingerprint('check: segments == 2048')).not.toBe(fingerprint('check: segments == 2049'));
  });

  it('pack a submission and read it back as it was', async () => {
    const made = await submissionLink(STUDIO, WORK);
    if (!made.ok) throw new Error(made.error);
    expect(made.link.startsWith('https://studio.example/meristem/#submission=1.')).toBe(true);
    const read = await unpackSubmission(made.link.split('#submission=')[1]);
    expect(read).toEqual({ ok: true, submission: WORK });
  });

  it('pack an assignment into a link, or link to its URL', async () => {
    const text = '---\ntitle: T\n---\n';
    const packed = await assignmentLink(STUDIO, { kind: 'packed' }, text);
    expect(await unpackAssignment(packed.split('#assignment=')[1])).toEqual({ ok: true, text });
    expect(await assignmentLink(STUDIO, { kind: 'url', url: 'https://course.example/a 1.md' }, text)).toBe('https://studio.example/meristem/?assignment=https%3A%2F%2Fcourse.example%2Fa%201.md');
  });

  it('refuse hostile submissions politely', async () => {
    const pack = async (value: unknown) => `1.${await packText(JSON.stringify(value))}`;
    const refusals = [
      ['2.abc', /newer Meristem/],
      ['1.!!!', /base64url/],
      [await pack([1, 2]), /does not hold a submission/],
      [await pack({ ...WORK, grammar: 3 }), /no grammar/],
      [await pack({ ...WORK, fingerprint: 'xyz' }), /which assignment/],
      [await pack({ ...WORK, name: 'n'.repeat(500) }), /malformed/],
      [await pack({ ...WORK, url: undefined }), /neither/],
      [`1.${await packText('x'.repeat(600 * 1024))}`, /inflates to more than/],
    ] as const;
    for (const [packed, message] of refusals) {
      const read = await unpackSubmission(packed);
      expect(read.ok, packed.slice(0, 20)).toBe(false);
      if (!read.ok) expect(read.error).toMatch(message);
    }
  });
});
