// A line-based diff of a variant's text against the first variant's: the lines removed, added and
// changed (a removed line followed by an added one in the same place), each with its line numbers,
// for the Variants view's diff lists. Common lines at the start and the end are skipped first; the
// middle is compared by the longest common subsequence of its lines, within a budget of cells (past
// it, the middle is said to be replaced whole, never a hang on a long text).

/** One line that differs. */
export interface DiffLine {
  kind: 'removed' | 'added' | 'changed';
  /** 1-based line in the first text (removed, changed). */
  before?: number;
  /** 1-based line in the other text (added, changed). */
  after?: number;
  /** The line in the first text. */
  old?: string;
  /** The line in the other text. */
  new?: string;
}

/** Most cells of the comparison table (lines × lines of the differing middle). */
export const MAX_DIFF_CELLS = 4_000_000;

const linesOf = (text: string) => text.replace(/\r\n?/g, '\n').replace(/\n$/, '').split('\n');

/** The differences of `other` from `first`, line by line, in order; empty when the texts are the same. */
export function lineDiff(first: string, other: string): DiffLine[] {
  const a = linesOf(first);
  const b = linesOf(other);
  let start = 0;
  while (start < a.length && start < b.length && a[start] === b[start]) start++;
  let endA = a.length;
  let endB = b.length;
  while (endA > start && endB > start && a[endA - 1] === b[endB - 1]) {
    endA--;
    endB--;
  }
  const ops = middleOps(a.slice(start, endA), b.slice(start, endB));
  return pairChanges(ops, a, b, start);
}

type Op = 'same' | 'removed' | 'added';

/** The edit script of `a` into `b` (longest common subsequence), or all removed then all added past the budget. */
function middleOps(a: readonly string[], b: readonly string[]): Op[] {
  const n = a.length;
  const m = b.length;
  if (n === 0 || m === 0 || (n + 1) * (m + 1) > MAX_DIFF_CELLS) return [...Array<Op>(n).fill('removed'), ...Array<Op>(m).fill('added')];
  // table[i][j]: the longest common subsequence of a[i..] and b[j..], row by row in one array.
  const width = m + 1;
  const table = new Uint32Array((n + 1) * width);
  for (let i = n - 1; i >= 0; i--)
    for (let j = m - 1; j >= 0; j--)
      table[i * width + j] = a[i] === b[j] ? table[(i + 1) * width + j + 1] + 1 : Math.max(table[(i + 1) * width + j], table[i * width + j + 1]);
  const ops: Op[] = [];
  let i = 0;
  let j = 0;
  while (i < n && j < m) {
    if (a[i] === b[j]) {
      ops.push('same');
      i++;
      j++;
    } else if (table[(i + 1) * width + j] >= table[i * width + j + 1]) {
      ops.push('removed');
      i++;
    } else {
      ops.push('added');
      j++;
    }
  }
  while (i++ < n) ops.push('removed');
  while (j++ < m) ops.push('added');
  return ops;
}

/** The script's lines, a run of removed lines and the added run after it paired line by line as changed. */
function pairChanges(ops: readonly Op[], a: readonly string[], b: readonly string[], start: number): DiffLine[] {
  const diff: DiffLine[] = [];
  let i = start;
  let j = start;
  let k = 0;
  while (k < ops.length) {
    if (ops[k] === 'same') {
      i++;
      j++;
      k++;
      continue;
    }
    const removed: number[] = [];
    const added: number[] = [];
    while (k < ops.length && ops[k] === 'removed') (removed.push(i++), k++);
    while (k < ops.length && ops[k] === 'added') (added.push(j++), k++);
    const paired = Math.min(removed.length, added.length);
    for (let p = 0; p < paired; p++) diff.push({ kind: 'changed', before: removed[p] + 1, after: added[p] + 1, old: a[removed[p]], new: b[added[p]] });
    for (const r of removed.slice(paired)) diff.push({ kind: 'removed', before: r + 1, old: a[r] });
    for (const d of added.slice(paired)) diff.push({ kind: 'added', after: d + 1, new: b[d] });
  }
  return diff;
}
