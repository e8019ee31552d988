// The context view's explanations in words, for a student: which rule a production is, what it did
// in the last step, and why it did or did not rewrite one module ("left context b expected at 3,
// found a"). Pure functions of the core's answers and the source text, tested without a page.
// Modules are written as the string panel writes them (numbers to 6 significant digits).
import type { Explanation, MatchReport, ProductionInfo } from '../../core';
import { shortModuleText, shortNumber } from './module-text';
import { plural } from '../preview';

/** The 1-based line of a UTF-16 offset. */
export function lineOf(source: string, offset: number): number {
  let line = 1;
  for (let i = 0; i < offset && i < source.length; i++) if (source.charCodeAt(i) === 10) line++;
  return line;
}

/** A production as the user knows it: `rule 2 (line 8: F -> FF)`, or its label for a labelled one. */
export function describeProduction(source: string, p: ProductionInfo): string {
  const text = source.slice(p.from, p.to).trim();
  return `${p.label ?? `rule ${p.index + 1}`} (line ${lineOf(source, p.from)}: ${text})`;
}

/** The condition of a production as written, or null. */
export function conditionText(source: string, p: ProductionInfo): string | null {
  return p.condition ? source.slice(p.condition.from, p.condition.to).trim() : null;
}

/**
 * What the panels show of a timed grammar (ABOP 6.1) derived at growth time `t` (the timeline's,
 * else its iterations), and where to look: its last step is the last round of replacements before t.
 */
export function stringAtTime(t: number): string {
  return (
    `The string at t = ${shortNumber(String(t))} (a timed module’s first parameter is its age). ` +
    'Put the cursor on a production to see where it fired in the last round before t, or click the plant to ask how a part of it was made.'
  );
}

/** What production `p` did in the last step, from its explanation's counts. */
export function countsInWords(source: string, p: ProductionInfo, e: Explanation): string {
  const name = describeProduction(source, p);
  const fired = `${name} fired ${plural(e.fired, 'time')} in the last step`;
  const condition = conditionText(source, p);
  const matched = p.context ? `${plural(e.contextMatched, 'module')} had its predecessor and contexts` : `${plural(e.contextMatched, 'module')} matched its predecessor`;
  if (condition === null) return `${fired}: ${matched}.`;
  const failed =
    e.conditionFailed === 0
      ? `the condition ${condition} held${e.contextMatched > 1 ? ' at all of them' : ''}`
      : `the condition ${condition} was false at ${e.conditionFailed} of them`;
  return `${fired}: ${matched}; ${failed}.`;
}

/**
 * How module `module` of the derived string (written `text`) was made: by production `p`, which
 * rewrote the module of the step before that `report` checked, with the contexts it matched.
 */
export function madeInWords(source: string, p: ProductionInfo, e: Explanation, report: MatchReport | null, module: number, text: string): string {
  const made = `This ${shortModuleText(text)} (module ${module} of the derived string) was written by ${describeProduction(source, p)}`;
  const from = report ? ` from ${shortModuleText(report.moduleText)} (module ${report.module} of the step before)` : '';
  const parts = report ? [contextInWords('left', report.left), contextInWords('right', report.right)].filter((s): s is string => s !== null) : [];
  const condition = conditionText(source, p);
  if (condition !== null) parts.push(`${condition} held`);
  const why = parts.length > 0 ? `: ${parts.join('; ')}` : '';
  return `${made}${from}${why}. That production fired ${plural(e.fired, 'time')} in the last step.`;
}

/** Module `module` of the derived string (written `text`), which no production rewrote in the last step. */
export function copiedInWords(module: number, text: string): string {
  return `This ${shortModuleText(text)} (module ${module} of the derived string) was copied: no production rewrote it in the last step.`;
}

/** Where a context check stood, in words (`left context b matched at 3`). */
function contextInWords(side: 'left' | 'right', check: MatchReport['left']): string | null {
  if (check.matched) return check.modules.length > 0 ? `${side} context matched at ${check.modules.join(', ')}` : null;
  const found = check.found === null ? `found the ${side === 'left' ? 'start' : 'end'} of the string` : `found ${shortModuleText(check.foundText ?? '')} at ${check.found}`;
  return `${side} context ${check.expected ?? ''} expected, ${found}`.replace('  ', ' ');
}

/**
 * Why production `p` did or did not rewrite the module `report` checked (`module` of the string
 * the last step read), in words: the predecessor, each context, the condition, and the outcome.
 * `rewriter` names the production that did rewrite it, if another did.
 */
export function reportInWords(source: string, p: ProductionInfo, report: MatchReport, rewriter?: ProductionInfo): string {
  const name = describeProduction(source, p);
  const at = `${shortModuleText(report.moduleText)} (module ${report.module} of the string before the last step)`;
  if (!report.predecessor) return `${name} cannot rewrite ${at}: it is not the production's predecessor.`;
  const parts = [contextInWords('left', report.left), contextInWords('right', report.right)].filter((s): s is string => s !== null);
  const condition = conditionText(source, p);
  if (report.condition !== null && condition !== null) parts.push(report.condition ? `${condition} held` : `${condition} was false`);
  const reasons = parts.length > 0 ? `: ${parts.join('; ')}` : '';
  const matched = report.left.matched && report.right.matched && report.condition !== false;
  let outcome: string;
  if (report.rewrittenBy === p.index) outcome = 'so it fired there.';
  else if (!matched) outcome = 'so it did not fire there.';
  else if (rewriter) outcome = `it matched, but ${describeProduction(source, rewriter)} rewrote it (the first production that matches wins; with weights, one of those that match is drawn).`;
  else outcome = 'it matched, but the module was copied.';
  return `${name} at ${at}${reasons} — ${outcome}`;
}
