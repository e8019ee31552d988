import { describe, expect, it } from 'vitest';
import { diagnosticList, NO_DIAGNOSTICS, type Diagnostic } from '../../core';
import { DiagnosticsFeed } from './diagnostics-feed';

const error: Diagnostic = { severity: 'error', code: 'E0109', message: 'm', fromByte: 0, toByte: 1, line: 1, column: 1 };

describe('DiagnosticsFeed', () => {
  it('answers when the build of the asked text is delivered', async () => {
    const feed = new DiagnosticsFeed();
    const asked = feed.diagnose('F[');
    feed.delivered('F[', diagnosticList([error]));
    expect([...(await asked)]).toEqual([error]);
    expect(feed.pending).toBe(0);
  });

  it('answers at once for the text built last', async () => {
    const feed = new DiagnosticsFeed();
    feed.delivered('F', NO_DIAGNOSTICS);
    expect(await feed.diagnose('F')).toHaveLength(0);
  });

  it('does not answer a question about one text with the build of another', async () => {
    const feed = new DiagnosticsFeed();
    let answered = false;
    void feed.diagnose('F[').then(() => (answered = true));
    feed.delivered('F', NO_DIAGNOSTICS);
    await Promise.resolve();
    expect(answered).toBe(false);
    expect(feed.pending).toBe(1);
  });

  it('releases older questions when a newer text is asked about', async () => {
    const feed = new DiagnosticsFeed();
    const old = feed.diagnose('F[');
    void feed.diagnose('F[]');
    expect(await old).toHaveLength(0);
    expect(feed.pending).toBe(1);
  });
});
