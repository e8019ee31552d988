import { describe, expect, it } from 'vitest';
import { decodeState, MAX_FRAGMENT, MAX_TEXT } from '../../share';
import { shareableLink } from './share-button';

/** Text that deflate cannot shrink much: `n` characters of a seeded pseudo-random grammar comment. */
function incompressible(n: number): string {
  let x = 12345;
  let text = 'axiom: F\n// ';
  while (text.length < n) {
    x = (x * 48271) % 2147483647; // Park–Miller: exact in doubles
    text += String.fromCharCode(33 + (x % 90));
  }
  return text;
}

describe('shareableLink', () => {
  it('gives the link of a state that a receiver opens', async () => {
    const state = { text: '#define onset = 2\naxiom: F(onset)', iterations: 3 };
    const link = await shareableLink(state);
    expect(link.ok).toBe(true);
    if (link.ok) expect(await decodeState(link.fragment)).toEqual({ ok: true, state });
  });

  it('refuses, with the length in words, a grammar whose link would be over the limit', async () => {
    const text = incompressible(120_000); // under the text limit, but its link is about 150,000 characters
    expect(text.length).toBeLessThan(MAX_TEXT);
    const link = await shareableLink({ text });
    expect(link).toEqual({ ok: false, why: expect.stringMatching(/^the link would be [\d,]+ characters long, and a link holds at most 65,536$/) });
  });

  it('refuses a grammar longer than a link may hold, saying why as the receiver would', async () => {
    const link = await shareableLink({ text: 'F'.repeat(MAX_TEXT + 1) }); // compresses well, but too long to open
    expect(link).toEqual({ ok: false, why: expect.stringMatching(/too long/) });
  });

  it('keeps a grammar just under the limit as a link', async () => {
    const text = incompressible(40_000);
    const link = await shareableLink({ text });
    expect(link.ok).toBe(true);
    if (link.ok) expect(link.fragment.length - 1).toBeLessThanOrEqual(MAX_FRAGMENT);
  });
});
