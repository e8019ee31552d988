import { EditorState } from '@codemirror/state';
import { describe, expect, it } from 'vitest';
import { diagnosticList, type Diagnostic } from '../core';
import { ProblemList } from './problem-list';
import { MAX_LIST_HEIGHT, ROW_HEIGHT, rowsInView, scrollFor } from './problems-panel';
import { markedDiagnostics, MAX_MARKED, problemRange, problemsField, problemsUpdate } from './problems-state';

function problem(from: number, message = 'bad'): Diagnostic {
  return { fromByte: from, toByte: from + 1, severity: 'error', message, code: 'E0105', line: 1, column: from + 1 };
}

/** The problems of an ASCII text long enough for them. */
function problems(list: Diagnostic[]): ProblemList {
  return ProblemList.of(' '.repeat(Math.max(0, ...list.map((d) => d.toByte))), diagnosticList(list));
}

/** What CodeMirror is given for `d`. */
function marker(d: Diagnostic): object {
  return { from: d.fromByte, to: d.toByte, severity: d.severity, message: d.message, source: d.code };
}

describe('the text’s markers', () => {
  it('are every problem up to MAX_MARKED', () => {
    const list = Array.from({ length: MAX_MARKED }, (_, i) => problem(2 * i));
    expect(markedDiagnostics(problems(list))).toEqual(list.map(marker));
  });

  it('past MAX_MARKED are the first ones and a note of how many follow, where the first unmarked starts', () => {
    const list = Array.from({ length: 100_000 }, (_, i) => problem(2 * i));
    const marked = markedDiagnostics(problems(list));
    expect(marked).toHaveLength(MAX_MARKED + 1);
    expect(marked.slice(0, MAX_MARKED)).toEqual(list.slice(0, MAX_MARKED).map(marker));
    expect(marked[MAX_MARKED]).toMatchObject({ from: 2 * MAX_MARKED, to: 2 * MAX_MARKED, severity: 'info' });
    expect(marked[MAX_MARKED].message).toMatch(/^99,000 more problems from here on are not marked in the text: Problems \(Ctrl\+Shift\+M\) lists all 100,000/);
  });

  it('come in the text’s order, the core’s order kept among equal ranges', () => {
    const list = problems([problem(9, 'c'), problem(1, 'a'), problem(9, 'd'), problem(1, 'b')]);
    expect(Array.from({ length: list.length }, (_, i) => list.at(i).message)).toEqual(['a', 'b', 'c', 'd']);
    expect(list.range(2)).toEqual({ from: 9, to: 10 });
  });
});

describe('the problems’ positions', () => {
  it('follow edits made after them', () => {
    let state = EditorState.create({ doc: 'axiom: F\n?\n?\n', extensions: [problemsField] });
    state = state.update(problemsUpdate(ProblemList.of(state.doc.toString(), diagnosticList([problem(9), problem(11)])))).state;
    state = state.update({ changes: { from: 0, insert: '// a comment\n' } }).state;
    expect(problemRange(state.field(problemsField), 1)).toEqual({ from: 24, to: 25 });
    expect(state.doc.sliceString(24, 25)).toBe('?');
  });
});

describe('the list’s rows in view', () => {
  it('are the visible ones and a few more, each in its place', () => {
    expect(rowsInView(0, 168, 100_000)).toEqual({ first: 0, last: 10, top: 0, height: 100_000 * ROW_HEIGHT });
    const r = rowsInView(50_000 * ROW_HEIGHT, 168, 100_000);
    expect(r.first).toBe(49_996);
    expect(r.last).toBe(50_010);
    expect(r.top).toBe(49_996 * ROW_HEIGHT);
  });

  it('reach the last row of a list too tall for the page, drawn where the view is', () => {
    const rows = 1_000_000;
    const end = rowsInView(MAX_LIST_HEIGHT - 168, 168, rows);
    expect(end.height).toBe(MAX_LIST_HEIGHT);
    expect(end.last).toBe(rows);
    expect(end.top + (end.last - 1 - end.first) * ROW_HEIGHT).toBeLessThanOrEqual(MAX_LIST_HEIGHT - ROW_HEIGHT);
    expect(rowsInView(scrollFor(654_321, 0, 168, rows), 168, rows).first).toBe(654_321);
  });

  it('scroll only as far as needed to show a row', () => {
    expect(scrollFor(3, 0, 168, 100)).toBe(0);
    expect(scrollFor(10, 0, 168, 100)).toBe(11 * ROW_HEIGHT - 168);
    expect(scrollFor(2, 10 * ROW_HEIGHT, 168, 100)).toBe(2 * ROW_HEIGHT);
  });
});
