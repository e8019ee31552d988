import { afterEach, describe, expect, it, vi } from 'vitest';

afterEach(() => {
  vi.doUnmock('./codec');
  vi.resetModules();
});

describe('the share codec on first use', () => {
  it('loads the codec once, and round-trips through it', async () => {
    const loader = await import('./codec-loader');
    const first = loader.loadCodec();
    expect(loader.loadCodec()).toBe(first);
    const fragment = await loader.encodeState({ text: 'axiom: F', iterations: 3 });
    expect(loader.hasSharedState(fragment)).toBe(true);
    expect(await loader.decodeState(fragment)).toEqual({ ok: true, state: { text: 'axiom: F', iterations: 3 } });
  });

  it('says so when the codec cannot be loaded, and tries again next time', async () => {
    vi.doMock('./codec', () => {
      throw new Error('offline');
    });
    const loader = await import('./codec-loader');
    const decoded = await loader.decodeState('#s=1.AAAA');
    expect(decoded).toEqual({ ok: false, error: expect.stringMatching(/could not load its link reader/) });
    await expect(loader.encodeState({ text: 'F' })).rejects.toThrow();
    vi.doUnmock('./codec');
    const fragment = await loader.encodeState({ text: 'axiom: F' });
    expect(await loader.decodeState(fragment)).toEqual({ ok: true, state: { text: 'axiom: F' } });
  });
});
