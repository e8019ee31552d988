// Diagnostics for the editor's linter, fed by the builds the worker delivers: the linter asks for
// the diagnostics of the current text and gets them when that text's build arrives (or at once if
// it already has), never by building on its own.
import { NO_DIAGNOSTICS, type DiagnosticList } from '../../core';

interface Waiter {
  source: string;
  resolve: (diagnostics: DiagnosticList) => void;
}

/** Hands each build's diagnostics to whoever asked for that text. */
export class DiagnosticsFeed {
  private last: { source: string; diagnostics: DiagnosticList } | undefined;
  private waiters: Waiter[] = [];

  /**
   * The diagnostics of `source`: at once when it is the last text built, else when its build is
   * delivered. Asking for a new text releases the older questions with no diagnostics (the linter
   * only ever asks about the current document, and drops answers about older ones).
   */
  diagnose(source: string): Promise<DiagnosticList> {
    if (this.last?.source === source) return Promise.resolve(this.last.diagnostics);
    for (const waiter of this.waiters) if (waiter.source !== source) waiter.resolve(NO_DIAGNOSTICS);
    this.waiters = this.waiters.filter((w) => w.source === source);
    return new Promise((resolve) => this.waiters.push({ source, resolve }));
  }

  /** A build of `source` was delivered. */
  delivered(source: string, diagnostics: DiagnosticList): void {
    this.last = { source, diagnostics };
    const ready = this.waiters.filter((w) => w.source === source);
    this.waiters = this.waiters.filter((w) => w.source !== source);
    for (const waiter of ready) waiter.resolve(diagnostics);
  }

  /** Questions still open (for tests). */
  get pending(): number {
    return this.waiters.length;
  }
}
