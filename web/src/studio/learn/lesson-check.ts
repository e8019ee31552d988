// The predicate language of lesson tasks (docs/LESSONS.md, "Checks"): comparisons joined by `and`,
// `or` and `not`, over facts of the plant on screen and functions of its derived string:
//
//   count("[") >= 8 and branch_order <= 3
//   segments == 625 and contains("F+F-F-F+F")
//
// Parsed by a small recursive-descent parser (never `eval`), at build time by the lessons plugin (a
// malformed check fails the build with its file and line) and again on the page, then evaluated on
// the last good build. Every answer is in words: "count("[") is 4, the task wants 8".
import type { PlantBuild, PlantInspector, PlantStats } from '../../core';
import { floretPositions, MAX_FLORETS, parastichyPair } from './parastichies.ts';
import { divergence, trunkWidthRatio } from './plant-measures.ts';

/** The facts a check may name, with what each means (docs/LESSONS.md lists the same). */
export const CHECK_FACTS = {
  modules: 'modules in the derived string',
  segments: 'segments the turtle drew',
  vertices: 'vertices of the mesh',
  triangles: 'triangles of the mesh',
  iterations: 'derivation steps applied',
  width: 'extent of the plant along x (left to right)',
  height: 'extent of the plant along y (bottom to top)',
  depth: 'extent of the plant along z (back to front)',
  left: 'how far the plant reaches to the left of its base (the origin), along -x; 0 when it stays right of it',
  right: 'how far the plant reaches to the right of its base (the origin), along +x; 0 when it stays left of it',
  branch_order: 'the deepest nesting of branches ([ inside [): 0 for a plant without branches',
  whorl: 'the most branches written side by side at one node: F[+F][-F]F has 2',
  seed: 'the seed the plant on screen was derived with (the Seed box, else the grammar\'s #seed)',
  text_seed: 'the seed the grammar\'s text writes with #seed; -1 when it writes none',
  parastichies_m: 'the fewer of the two families of spirals (contact parastichies) of the plant\'s spheres (florets), counted in the middle third of them; 0 for fewer than 12',
  parastichies_n: 'the more numerous of the two families of spirals of the plant\'s spheres (florets); 0 for fewer than 12',
  trunk_width_ratio: 'the first segment\'s drawn width (at its base) ÷ the plant\'s height: the trunk\'s proportion',
  divergence: 'the angle in degrees (0 to 180) about the plant\'s axis between consecutive spheres (organs, florets) in the order drawn, the median over them; 0 for fewer than 3',
} as const;

/** A fact a check may name. */
export type CheckFact = keyof typeof CHECK_FACTS;

/** The functions of the derived string a check may call, with what each means. */
export const CHECK_FUNCTIONS = {
  count: 'count("F"): how many modules of the derived string are named F (whatever their parameters)',
  contains: 'contains("F[+F]"): whether the derived string, written as the string panel shows it, contains this text',
  position: 'position("K"): where the first module named K stands in the derived string, counting from 1 at its start (the base); 0 when there is none',
} as const;

type Comparison = '==' | '!=' | '<' | '<=' | '>' | '>=';
type Arithmetic = '+' | '-' | '*' | '/';

/** A number-valued part of a check. */
type NumberNode =
  | { kind: 'number'; value: number; text: string }
  | { kind: 'fact'; name: CheckFact; text: string }
  | { kind: 'count' | 'position'; module: string; text: string }
  | { kind: 'arithmetic'; op: Arithmetic; left: NumberNode; right: NumberNode; text: string }
  | { kind: 'negate'; operand: NumberNode; text: string };

/** A truth-valued part of a check: a whole check is one. */
export type CheckNode =
  | { kind: 'compare'; op: Comparison; left: NumberNode; right: NumberNode; text: string }
  | { kind: 'contains'; needle: string; text: string }
  | { kind: 'and' | 'or'; left: CheckNode; right: CheckNode; text: string }
  | { kind: 'not'; operand: CheckNode; text: string };

/** Why a check could not be read: the message and the 0-based offset in the check's text. */
export interface CheckSyntaxError {
  message: string;
  offset: number;
}

/** A check read, or why not. */
export type ParsedCheck = { ok: true; check: CheckNode } | { ok: false; error: CheckSyntaxError };

interface Token {
  kind: 'number' | 'string' | 'word' | 'op' | 'end';
  text: string;
  /** The string's contents, without quotes and escapes. */
  value: string;
  offset: number;
}

class SyntaxProblem extends Error {
  constructor(
    message: string,
    readonly offset: number,
  ) {
    super(message);
  }
}

const OPERATORS = ['==', '!=', '<=', '>=', '<', '>', '+', '-', '*', '/', '(', ')'];

function tokenize(source: string): Token[] {
  const tokens: Token[] = [];
  let i = 0;
  while (i < source.length) {
    const c = source[i];
    if (/\s/.test(c)) {
      i++;
      continue;
    }
    const start = i;
    const number = /^(\d+(\.\d*)?|\.\d+)/.exec(source.slice(i));
    const word = /^[A-Za-z_][A-Za-z0-9_]*/.exec(source.slice(i));
    if (number) {
      i += number[0].length;
      tokens.push({ kind: 'number', text: number[0], value: number[0], offset: start });
    } else if (word) {
      i += word[0].length;
      tokens.push({ kind: 'word', text: word[0], value: word[0], offset: start });
    } else if (c === '"') {
      let value = '';
      for (i++; i < source.length && source[i] !== '"'; i++) {
        if (source[i] === '\\' && i + 1 < source.length) i++;
        value += source[i];
      }
      if (i >= source.length) throw new SyntaxProblem('this text has no closing "', start);
      i++;
      tokens.push({ kind: 'string', text: source.slice(start, i), value, offset: start });
    } else {
      const op = OPERATORS.find((o) => source.startsWith(o, i));
      if (!op) throw new SyntaxProblem(c === '=' ? 'write == to compare' : `"${c}" has no meaning in a check`, start);
      i += op.length;
      tokens.push({ kind: 'op', text: op, value: op, offset: start });
    }
  }
  tokens.push({ kind: 'end', text: '', value: '', offset: source.length });
  return tokens;
}

function arithmetic(op: string, left: NumberNode, right: NumberNode, text: string): NumberNode {
  return { kind: 'arithmetic', op: op as Arithmetic, left, right, text };
}

/** Recursive descent over the tokens; each node keeps the text it was read from. */
class Parser {
  private at = 0;
  private readonly tokens: Token[];

  constructor(private readonly source: string) {
    this.tokens = tokenize(source);
  }

  check(): CheckNode {
    const node = this.bool();
    const rest = this.peek();
    if (rest.kind !== 'end') throw new SyntaxProblem(`"${rest.text}" was not expected here: join comparisons with and, or`, rest.offset);
    return node;
  }

  private peek(): Token {
    return this.tokens[this.at];
  }

  private take(): Token {
    return this.tokens[this.at++];
  }

  private isWord(word: string): boolean {
    const t = this.peek();
    return t.kind === 'word' && t.text === word;
  }

  private isOp(...ops: string[]): boolean {
    const t = this.peek();
    return t.kind === 'op' && ops.includes(t.text);
  }

  private expectOp(op: string, what: string): void {
    const t = this.peek();
    if (t.kind !== 'op' || t.text !== op) throw new SyntaxProblem(`expected ${op} ${what}`, t.offset);
    this.take();
  }

  private textFrom(offset: number): string {
    const end = this.tokens[this.at - 1];
    return this.source.slice(offset, end.offset + end.text.length).trim();
  }

  /** One level of left-associative binary operators, `next (op next)*`; `operator` names the `op` ahead, if any. */
  private leftAssociative<N>(next: () => N, operator: () => string | undefined, join: (op: string, left: N, right: N, text: string) => N): N {
    const start = this.peek().offset;
    let left = next();
    for (let op = operator(); op !== undefined; op = operator()) {
      this.take();
      left = join(op, left, next(), this.textFrom(start));
    }
    return left;
  }

  /** `a or b`, `a and b` (and binds tighter), `not a`. */
  private bool(): CheckNode {
    const or = () => (this.isWord('or') ? 'or' : undefined);
    return this.leftAssociative(() => this.conjunction(), or, (_, left, right, text): CheckNode => ({ kind: 'or', left, right, text }));
  }

  private conjunction(): CheckNode {
    const and = () => (this.isWord('and') ? 'and' : undefined);
    return this.leftAssociative(() => this.negation(), and, (_, left, right, text): CheckNode => ({ kind: 'and', left, right, text }));
  }

  private negation(): CheckNode {
    return this.prefixed(() => this.isWord('not'), () => this.truth(), (operand, text) => ({ kind: 'not', operand, text }));
  }

  /** A comparison, `contains(…)`, or a parenthesised check. */
  private truth(): CheckNode {
    const start = this.peek();
    if (start.kind === 'word' && start.text === 'contains') {
      const needle = this.call();
      return { kind: 'contains', needle, text: this.textFrom(start.offset) };
    }
    if (start.kind === 'op' && start.text === '(' && this.parenthesisHoldsTruth()) {
      this.take();
      const inner = this.bool();
      this.expectOp(')', 'to close (');
      return inner;
    }
    const left = this.sum();
    const op = this.peek();
    if (!this.isOp('==', '!=', '<', '<=', '>', '>=')) {
      throw new SyntaxProblem(`${left.text} is a number: compare it with == != < <= > >= (e.g. ${left.text} >= 3)`, op.offset);
    }
    this.take();
    const right = this.sum();
    if (this.isOp('==', '!=', '<', '<=', '>', '>=')) throw new SyntaxProblem('compare two things at a time: a < b and b < c', this.peek().offset);
    return { kind: 'compare', op: op.text as Comparison, left, right, text: this.textFrom(start.offset) };
  }

  /** Whether the `(` here opens a check (`(a or b)`) rather than a number (`(a + b) * 2`). */
  private parenthesisHoldsTruth(): boolean {
    let depth = 0;
    for (let i = this.at; i < this.tokens.length; i++) {
      const t = this.tokens[i];
      if (t.kind === 'op' && t.text === '(') depth++;
      else if (t.kind === 'op' && t.text === ')' && --depth === 0) return false;
      else if (depth === 1 && ((t.kind === 'word' && ['and', 'or', 'not', 'contains'].includes(t.text)) || (t.kind === 'op' && /[=<>!]/.test(t.text)))) return true;
    }
    return false;
  }

  private sum(): NumberNode {
    return this.leftAssociative(() => this.product(), () => this.arithmeticAhead('+', '-'), arithmetic);
  }

  private product(): NumberNode {
    return this.leftAssociative(() => this.unary(), () => this.arithmeticAhead('*', '/'), arithmetic);
  }

  private arithmeticAhead(...ops: Arithmetic[]): Arithmetic | undefined {
    return this.isOp(...ops) ? (this.peek().text as Arithmetic) : undefined;
  }

  private unary(): NumberNode {
    return this.prefixed(() => this.isOp('-'), () => this.atom(), (operand, text) => ({ kind: 'negate', operand, text }));
  }

  /**
   * A prefix operator (`not`, `-`: `hasPrefix` says whether one is next) and its operand, made by
   * `make` with the text of both; the operand may be prefixed again. Without one, `operand()`.
   */
  private prefixed<T>(hasPrefix: () => boolean, operand: () => T, make: (operand: T, text: string) => T): T {
    const start = this.peek().offset;
    if (!hasPrefix()) return operand();
    this.take();
    return make(this.prefixed(hasPrefix, operand, make), this.textFrom(start));
  }

  private atom(): NumberNode {
    const t = this.peek();
    if (t.kind === 'number') {
      this.take();
      return { kind: 'number', value: Number(t.text), text: t.text };
    }
    if (t.kind === 'op' && t.text === '(') {
      this.take();
      const inner = this.sum();
      this.expectOp(')', 'to close (');
      return { ...inner, text: this.textFrom(t.offset) };
    }
    if (t.kind === 'word' && (t.text === 'count' || t.text === 'position')) {
      const module = this.call();
      if (module === '') throw new SyntaxProblem(`${t.text}("") names no module`, t.offset);
      return { kind: t.text, module, text: this.textFrom(t.offset) };
    }
    if (t.kind === 'word' && t.text in CHECK_FACTS) {
      this.take();
      return { kind: 'fact', name: t.text as CheckFact, text: t.text };
    }
    if (t.kind === 'word' && t.text === 'contains') throw new SyntaxProblem('contains(…) is true or false, not a number', t.offset);
    if (t.kind === 'word') {
      const known = [...Object.keys(CHECK_FACTS), ...Object.keys(CHECK_FUNCTIONS)].join(', ');
      throw new SyntaxProblem(`"${t.text}" is not a fact or function of checks (they are: ${known})`, t.offset);
    }
    throw new SyntaxProblem(t.kind === 'end' ? 'the check ends too early' : `expected a number, a fact or count("…"), not "${t.text}"`, t.offset);
  }

  /** `name("text")`: the text. */
  private call(): string {
    const name = this.take();
    this.expectOp('(', `after ${name.text}`);
    const argument = this.peek();
    if (argument.kind !== 'string') throw new SyntaxProblem(`${name.text}(…) takes one text in double quotes, e.g. ${name.text}("F")`, argument.offset);
    this.take();
    this.expectOp(')', `after ${name.text}'s text`);
    return argument.value;
  }
}

/** Reads a check; never throws. */
export function parseCheck(source: string): ParsedCheck {
  try {
    return { ok: true, check: new Parser(source).check() };
  } catch (error) {
    if (error instanceof SyntaxProblem) return { ok: false, error: { message: error.message, offset: error.offset } };
    throw error;
  }
}

/** Whether `node` (or any part of it) satisfies `test`. */
function mentions(node: CheckNode | NumberNode, test: (node: NumberNode) => boolean): boolean {
  switch (node.kind) {
    case 'compare':
    case 'and':
    case 'or':
    case 'arithmetic':
      return mentions(node.left, test) || mentions(node.right, test);
    case 'not':
    case 'negate':
      return mentions(node.operand, test);
    case 'contains':
      return false;
    default:
      return test(node);
  }
}

/** Whether evaluating `check` needs the florets' positions (a parastichy fact or the divergence). */
export function needsFlorets(check: CheckNode): boolean {
  return mentions(check, (n) => n.kind === 'fact' && (n.name === 'parastichies_m' || n.name === 'parastichies_n' || n.name === 'divergence'));
}

/** Whether evaluating `check` needs the trunk's proportion (read off the mesh's first tube). */
function needsTrunk(check: CheckNode): boolean {
  return mentions(check, (n) => n.kind === 'fact' && n.name === 'trunk_width_ratio');
}

/** Whether evaluating `check` needs the derived string (not only the stats). */
export function needsDerivedString(check: CheckNode): boolean {
  const numeric = (node: NumberNode): boolean =>
    node.kind === 'count' ||
    node.kind === 'position' ||
    (node.kind === 'fact' && (node.name === 'branch_order' || node.name === 'whorl')) ||
    (node.kind === 'arithmetic' && (numeric(node.left) || numeric(node.right))) ||
    (node.kind === 'negate' && numeric(node.operand));
  switch (check.kind) {
    case 'compare':
      return numeric(check.left) || numeric(check.right);
    case 'contains':
      return true;
    case 'not':
      return needsDerivedString(check.operand);
    default:
      return needsDerivedString(check.left) || needsDerivedString(check.right);
  }
}

/** What a check is evaluated on: the build's stats and, when needed, its derived string. */
export interface PlantFacts {
  stats: PlantStats;
  /** The derived string's modules as the string panel writes them (`F`, `A(1,2)`, `[`). */
  modules?: readonly string[];
  /** The florets' positions (`parastichies.ts`), for the parastichy facts (none: 0). */
  florets?: readonly number[][];
  /** The seed the plant was derived with (`PlantBuild.seed`). */
  seed?: number;
  /** The seed the grammar's text writes (`written-seed.ts`); undefined when it writes none. */
  textSeed?: number;
  /** The trunk's drawn width ÷ the plant's height (`plant-measures.ts`), when a check needs it. */
  trunkWidthRatio?: number;
}

/** The most modules whose texts a check fetches from the build's inspector. */
export const MAX_CHECKED_MODULES = 500_000;

/** The facts of one build for one check, or why they cannot be had. */
export type FactsOutcome = { ok: true; facts: PlantFacts } | { ok: false; reason: string };

/**
 * The facts of a build without errors that `check` reads: the stats, and the whole derived string
 * (`build.derived` is cut short) from the inspector when the check needs it.
 */
export async function plantFacts(check: CheckNode, build: PlantBuild, inspector: Pick<PlantInspector, 'moduleTexts'>, textSeed?: number): Promise<FactsOutcome> {
  const florets = needsFlorets(check) ? floretPositions(build.mesh) : undefined;
  if (florets && florets.length > MAX_FLORETS) {
    return { ok: false, reason: `the plant has ${florets.length.toLocaleString('en')} spheres, more than the parastichy count reads (${MAX_FLORETS.toLocaleString('en')}); try fewer iterations` };
  }
  const trunk = needsTrunk(check) ? trunkWidthRatio(build.mesh, build.stats) : undefined;
  if (trunk !== undefined && Number.isNaN(trunk)) {
    return { ok: false, reason: 'the plant has no trunk drawn as a tube (the Lines mode draws lines): choose Tubes in the view, then check again' };
  }
  const known = { stats: build.stats, florets, seed: build.seed, textSeed, trunkWidthRatio: trunk };
  if (!needsDerivedString(check)) return { ok: true, facts: known };
  const count = build.moduleCount;
  if (count > MAX_CHECKED_MODULES) {
    return { ok: false, reason: `the derived string has ${count.toLocaleString('en')} modules, more than the check reads; try fewer iterations` };
  }
  const modules = await inspector.moduleTexts(0, count);
  if (modules.length !== count) return { ok: false, reason: 'the plant changed while it was being checked; check again' };
  return { ok: true, facts: { ...known, modules } };
}

/** The answer of a check: whether it holds, and the values that made it so, in words. */
export interface CheckAnswer {
  pass: boolean;
  /** For a pass, the values compared; for a fail, what is wrong and what the task wants. */
  reasons: string[];
}

/** Facts read off the derived string and the mesh, computed once per evaluation. */
class StringFacts {
  private names: string[] | undefined;
  private joined: string | undefined;
  private counts: Map<string, number> | undefined;
  private structure: { branchOrder: number; whorl: number } | undefined;
  private parastichies: [number, number] | undefined;
  private readonly modules: readonly string[] | undefined;

  constructor(readonly facts: PlantFacts) {
    this.modules = facts.modules;
  }

  /** The contact parastichy pair of the plant's spheres ([0, 0] without florets or with too few). */
  pair(): [number, number] {
    return (this.parastichies ??= parastichyPair(this.facts.florets ?? []));
  }

  /** Where the first module named `name` stands, from 1; 0 when none does. */
  position(name: string): number {
    return this.moduleNames().indexOf(name) + 1;
  }

  private moduleNames(): readonly string[] {
    return (this.names ??= this.list().map((m) => {
      const paren = m.indexOf('(');
      return paren < 0 ? m : m.slice(0, paren);
    }));
  }

  private list(): readonly string[] {
    if (!this.modules) throw new Error('this check needs the derived string');
    return this.modules;
  }

  text(): string {
    return (this.joined ??= this.list().join(''));
  }

  count(name: string): number {
    if (!this.counts) {
      this.counts = new Map();
      for (const n of this.moduleNames()) this.counts.set(n, (this.counts.get(n) ?? 0) + 1);
    }
    return this.counts.get(name) ?? 0;
  }

  /** The deepest nesting of `[`, and the longest run of sibling branches (`]` directly followed by `[`). */
  shape(): { branchOrder: number; whorl: number } {
    if (this.structure) return this.structure;
    let depth = 0;
    let branchOrder = 0;
    let whorl = 0;
    const runs: number[] = [0]; // per open depth: sibling branches side by side so far
    let closedJustNow = false;
    for (const m of this.list()) {
      if (m === '[') {
        const run = closedJustNow ? runs[depth] + 1 : 1;
        runs[depth] = run;
        whorl = Math.max(whorl, run);
        depth++;
        runs[depth] = 0;
        branchOrder = Math.max(branchOrder, depth);
        closedJustNow = false;
      } else if (m === ']') {
        depth = Math.max(0, depth - 1);
        closedJustNow = true;
      } else closedJustNow = false;
    }
    return (this.structure = { branchOrder, whorl });
  }
}

function factValue(name: CheckFact, stats: PlantStats, strings: StringFacts): number {
  const [min, max] = stats.bounds;
  switch (name) {
    case 'width':
      return max[0] - min[0];
    case 'height':
      return max[1] - min[1];
    case 'depth':
      return max[2] - min[2];
    case 'left':
      return Math.max(0, -min[0]);
    case 'right':
      return Math.max(0, max[0]);
    case 'branch_order':
      return strings.shape().branchOrder;
    case 'whorl':
      return strings.shape().whorl;
    case 'seed':
      return strings.facts.seed ?? Number.NaN;
    case 'text_seed':
      return strings.facts.textSeed ?? -1;
    case 'parastichies_m':
      return strings.pair()[0];
    case 'parastichies_n':
      return strings.pair()[1];
    case 'trunk_width_ratio':
      return strings.facts.trunkWidthRatio ?? Number.NaN;
    case 'divergence':
      return divergence(strings.facts.florets ?? []);
    default:
      return stats[name];
  }
}

function numberValue(node: NumberNode, stats: PlantStats, strings: StringFacts): number {
  switch (node.kind) {
    case 'number':
      return node.value;
    case 'fact':
      return factValue(node.name, stats, strings);
    case 'count':
      return strings.count(node.module);
    case 'position':
      return strings.position(node.module);
    case 'negate':
      return -numberValue(node.operand, stats, strings);
    case 'arithmetic': {
      const a = numberValue(node.left, stats, strings);
      const b = numberValue(node.right, stats, strings);
      return node.op === '+' ? a + b : node.op === '-' ? a - b : node.op === '*' ? a * b : a / b;
    }
  }
}

/** A number as a person reads it: integers whole, others to 4 significant digits. */
export function spokenNumber(value: number): string {
  if (Number.isInteger(value)) return String(value);
  if (!Number.isFinite(value)) return String(value);
  return String(Number(value.toPrecision(4)));
}

const WANTS: Record<Comparison, string> = { '==': '', '!=': 'anything but ', '<': 'less than ', '<=': 'at most ', '>': 'more than ', '>=': 'at least ' };

function holds(op: Comparison, a: number, b: number): boolean {
  const near = Math.abs(a - b) <= 1e-9 * Math.max(1, Math.abs(a), Math.abs(b));
  switch (op) {
    case '==':
      return near;
    case '!=':
      return !near;
    case '<':
      return a < b && !near;
    case '<=':
      return a < b || near;
    case '>':
      return a > b && !near;
    case '>=':
      return a > b || near;
  }
}

function answer(node: CheckNode, stats: PlantStats, strings: StringFacts): CheckAnswer {
  switch (node.kind) {
    case 'compare': {
      const a = numberValue(node.left, stats, strings);
      const b = numberValue(node.right, stats, strings);
      const pass = holds(node.op, a, b);
      const wanted = node.right.kind === 'number' ? node.right.text : `${node.right.text} (${spokenNumber(b)})`;
      const is = node.left.kind === 'number' ? node.left.text : `${node.left.text} is ${spokenNumber(a)}`;
      return { pass, reasons: [pass ? is : `${is}, the task wants ${WANTS[node.op]}${wanted}`] };
    }
    case 'contains': {
      const pass = strings.text().includes(node.needle);
      return { pass, reasons: [`the derived string ${pass ? 'contains' : 'does not contain'} ${node.needle}`] };
    }
    case 'not': {
      const inner = answer(node.operand, stats, strings);
      if (node.operand.kind === 'contains') {
        const reason = inner.pass ? `the derived string contains ${node.operand.needle}, the task wants it not to` : inner.reasons[0];
        return { pass: !inner.pass, reasons: [reason] };
      }
      const reason = inner.pass ? `${inner.reasons.join('; ')}, the task wants not (${node.operand.text})` : `not (${node.operand.text})`;
      return { pass: !inner.pass, reasons: [reason] };
    }
    case 'and': {
      const a = answer(node.left, stats, strings);
      const b = answer(node.right, stats, strings);
      const pass = a.pass && b.pass;
      return { pass, reasons: pass ? [...a.reasons, ...b.reasons] : [...(a.pass ? [] : a.reasons), ...(b.pass ? [] : b.reasons)] };
    }
    case 'or': {
      const a = answer(node.left, stats, strings);
      const b = answer(node.right, stats, strings);
      if (a.pass || b.pass) return { pass: true, reasons: a.pass ? a.reasons : b.reasons };
      return { pass: false, reasons: [`${a.reasons.join('; ')}, or ${b.reasons.join('; ')}`] };
    }
  }
}

/**
 * Evaluates a check on a plant. Throws only if the check needs the derived string and `facts`
 * has none (see {@link needsDerivedString}).
 */
export function evaluateCheck(check: CheckNode, facts: PlantFacts): CheckAnswer {
  return answer(check, facts.stats, new StringFacts(facts));
}

/** The answer as one sentence: "Passed: count("[") is 8." or "Not yet: count("[") is 4, the task wants 8." */
export function spokenAnswer(result: CheckAnswer): string {
  return `${result.pass ? 'Passed' : 'Not yet'}: ${result.reasons.join('; ')}.`;
}
