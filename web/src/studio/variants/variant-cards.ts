// The Variants view's list under the figure: a card per plant with its caption, seed and
// iterations, its text (editable: a copy to change, or a grammar pasted in), its figures (modules,
// segments, height) and the lines in which its text differs from the first plant's. Text only,
// in text nodes (a variant's text comes from a link, never trusted as HTML).
import type { SharedVariant } from '../../share';
import { MAX_CAPTION } from '../../share/variants-state';
import { el } from '../page/make-element';
import { lineDiff, type DiffLine } from './line-diff';

/** What a card shows of its plant once grown. */
export interface VariantFigures {
  modules: number;
  segments: number;
  /** From the lowest to the highest point, in model units. */
  height: number;
}

/** Most diff lines a card lists (the rest are counted). */
const MAX_LISTED = 60;

/** What the cards tell the view. */
export interface CardsHost {
  /** A variant's caption, seed, iterations or text changed (`regrow`: its plant must be grown again). */
  edited(index: number, regrow: boolean): void;
  removed(index: number): void;
}

const whole = (input: HTMLInputElement): number | undefined => (input.value.trim() === '' || !Number.isSafeInteger(input.valueAsNumber) || input.valueAsNumber < 0 ? undefined : input.valueAsNumber);

/** A number for a card: grouped thousands, a height to three significant digits. */
const count = (n: number) => n.toLocaleString('en-US');
const length = (n: number) => (Math.abs(n) >= 1000 ? Math.round(n).toLocaleString('en-US') : String(Number(n.toPrecision(3))));

/** The figures in words. */
export function figuresText(figures: VariantFigures): string {
  return `${count(figures.modules)} modules · ${count(figures.segments)} segments · height ${length(figures.height)}`;
}

export class VariantCards {
  private cards: { figures: HTMLElement; diff: HTMLElement }[] = [];

  constructor(
    private readonly list: HTMLElement,
    private readonly host: CardsHost,
  ) {}

  /** Makes a card for each of `variants` (the array is edited in place as the user types). */
  render(variants: SharedVariant[], limits: { min: number }): void {
    this.cards = [];
    this.list.replaceChildren(...variants.map((variant, i) => this.card(variants, variant, i, variants.length > limits.min)));
    this.showDiffs(variants);
  }

  /** Each plant's figures, or why it has none. */
  showFigures(figures: readonly (VariantFigures | string)[]): void {
    figures.forEach((f, i) => {
      const card = this.cards[i];
      if (card) card.figures.textContent = typeof f === 'string' ? f : figuresText(f);
    });
  }

  /** Each card's differences from the first plant. */
  showDiffs(variants: readonly SharedVariant[]): void {
    const first = variants[0];
    variants.forEach((variant, i) => {
      const card = this.cards[i];
      if (!card) return;
      if (i === 0) {
        card.diff.replaceChildren(el('p', { className: 'variant-diff-none' }, 'The others are compared with this text.'));
        return;
      }
      const diff = lineDiff(first.text, variant.text);
      const note = diff.length === 0 ? 'Same text as plant 1' : `${diff.length} ${diff.length === 1 ? 'line differs' : 'lines differ'} from plant 1`;
      const seeds = variant.seed !== first.seed ? `; seed ${variant.seed ?? 'of the grammar'} (plant 1: ${first.seed ?? 'of the grammar'})` : '';
      const rows = diff.slice(0, MAX_LISTED).flatMap(diffRows);
      const more = diff.length > MAX_LISTED ? [el('li', { className: 'diff-more' }, `… and ${diff.length - MAX_LISTED} more`)] : [];
      card.diff.replaceChildren(el('p', { className: 'variant-diff-none' }, note + seeds), el('ol', { className: 'variant-diff', ariaLabel: `Differences of plant ${i + 1} from plant 1` }, ...rows, ...more));
    });
  }

  private card(variants: SharedVariant[], variant: SharedVariant, i: number, removable: boolean): HTMLElement {
    const caption = el('input', { type: 'text', value: variant.caption ?? '', placeholder: `plant ${i + 1}`, maxLength: MAX_CAPTION, testid: 'variant-caption' });
    caption.setAttribute('aria-label', `Caption of plant ${i + 1}`);
    const seed = el('input', { type: 'number', min: '0', step: '1', value: variant.seed === undefined ? '' : String(variant.seed), placeholder: 'grammar’s', inputMode: 'numeric' });
    const iterations = el('input', { type: 'number', min: '0', step: '1', value: variant.iterations === undefined ? '' : String(variant.iterations), placeholder: 'grammar’s', inputMode: 'numeric' });
    const text = el('textarea', { value: variant.text, spellcheck: false, rows: 8, testid: 'variant-text' });
    text.setAttribute('aria-label', `Grammar of plant ${i + 1}`);
    const remove = el('button', { type: 'button', className: 'icon', textContent: '×', disabled: !removable, title: 'Remove this plant' });
    remove.setAttribute('aria-label', `Remove plant ${i + 1}`);
    const figures = el('p', { className: 'variant-figures', testid: 'variant-figures' }, 'Not grown yet');
    const diff = el('div', { className: 'variant-diff-box', testid: 'variant-diff' });
    caption.addEventListener('input', () => {
      variant.caption = caption.value.trim() === '' ? undefined : caption.value;
      this.host.edited(i, false);
    });
    for (const [input, key] of [
      [seed, 'seed'],
      [iterations, 'iterations'],
    ] as const)
      input.addEventListener('input', () => {
        variant[key] = whole(input);
        if (key === 'seed') this.showDiffs(variants);
        this.host.edited(i, true);
      });
    text.addEventListener('input', () => {
      variant.text = text.value;
      this.showDiffs(variants);
      this.host.edited(i, true);
    });
    remove.addEventListener('click', () => this.host.removed(i));
    this.cards.push({ figures, diff });
    return el(
      'li',
      { className: 'variant-card', testid: 'variant-card' },
      el('div', { className: 'variant-card-head' }, el('strong', {}, `${i + 1}`), caption, remove),
      el('div', { className: 'variant-card-fields' }, el('label', { className: 'field' }, 'Seed ', seed), el('label', { className: 'field' }, 'Iterations ', iterations)),
      figures,
      // A pasted plant's text, or a copy of plant 1's, open for editing.
      el('details', { open: variant.text === '' || (i > 0 && variant.text === variants[0].text && variant.seed === variants[0].seed) }, el('summary', {}, 'Text'), text),
      diff,
    );
  }
}

/** A diff line as list rows: a changed line as the old row and the new. */
function diffRows(line: DiffLine): HTMLElement[] {
  const row = (sign: '−' | '+', kind: string, number: number | undefined, text: string | undefined) =>
    el('li', { className: `diff-${kind}` }, el('span', { className: 'diff-sign', ariaHidden: 'true' }, sign), el('span', { className: 'diff-number' }, `${kind === 'removed' ? 'was' : 'now'} line ${number ?? ''}`), el('code', {}, text === '' ? ' ' : (text ?? '')));
  if (line.kind === 'removed') return [row('−', 'removed', line.before, line.old)];
  if (line.kind === 'added') return [row('+', 'added', line.after, line.new)];
  return [row('−', 'removed', line.before, line.old), row('+', 'added', line.after, line.new)];
}
