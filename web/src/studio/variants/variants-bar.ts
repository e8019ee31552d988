// The Variants view's bar: making the row (a constant at several values, several seeds, a copy of
// the grammar on screen, an example, a pasted text), the scale, the progress with Stop, the
// downloads and Close. Made in code (the page's HTML carries only the Variants button).
import type { StageScale } from '../../view/stages-layout';
import { fetchExample } from '../gallery/gallery';
import { fetchManifest } from '../gallery/manifest-fetch';
import { el } from '../page/make-element';
import { MAX_CAPTION } from '../../share/variants-state';

/** What the bar asks of the view. */
export interface BarActions {
  /** The row made from the plant on screen: `define` a constant `name` at the typed values, or the typed `seeds`. */
  make(kind: 'define' | 'seeds', name: string, values: string): void;
  /** A plant of `text` added to the row. */
  add(text: string, caption: string): void;
  /** A copy of the grammar on screen added to the row. */
  addShown(): void;
  /** The constants of the grammar on screen that may be varied (read again each time the choice is opened). */
  constants(): string[];
  rescaled(): void;
  stop(): void;
  png(): void;
  svg(): void;
  close(): void;
}

const button = (text: string, title: string, testid: string, click: () => void) => {
  const made = el('button', { type: 'button', textContent: text, title, testid });
  made.addEventListener('click', click);
  return made;
};

export class VariantsBar {
  readonly element: HTMLElement;
  private readonly constant = el('select', { testid: 'variants-constant' });
  private readonly values = el('input', { type: 'text', placeholder: '20, 25, 30', testid: 'variants-values', inputMode: 'decimal' });
  private readonly seeds = el('input', { type: 'text', placeholder: '1, 2, 3', testid: 'variants-seeds', inputMode: 'numeric' });
  private readonly example = el('select', { testid: 'variants-example' });
  private readonly scaleChoice = el('select', { testid: 'variants-scale' });
  private readonly status = el('span', { className: 'stages-status', testid: 'variants-status', role: 'status' });
  private readonly stopButton: HTMLButtonElement;
  private examplesListed = false;

  constructor(private readonly actions: BarActions) {
    this.constant.setAttribute('aria-label', 'The constant to vary');
    // The grammar on screen may have changed since the view opened: its constants are read again.
    for (const type of ['focus', 'pointerdown'] as const) this.constant.addEventListener(type, () => this.showConstants(actions.constants()));
    this.values.setAttribute('aria-label', 'Its values, e.g. 20, 25, 30');
    this.seeds.setAttribute('aria-label', 'Seeds, e.g. 1, 2, 3');
    this.example.setAttribute('aria-label', 'Add an example from the gallery');
    this.example.append(el('option', { value: '', textContent: '+ Example…' }));
    this.example.addEventListener('focus', () => void this.listExamples());
    this.example.addEventListener('pointerdown', () => void this.listExamples());
    this.example.addEventListener('change', () => void this.addExample());
    this.scaleChoice.setAttribute('aria-label', 'Scale of the plants');
    this.scaleChoice.append(el('option', { value: 'one', textContent: 'one scale' }), el('option', { value: 'each', textContent: 'each fitted' }));
    this.scaleChoice.addEventListener('change', () => actions.rescaled());
    this.status.setAttribute('aria-live', 'polite');
    this.stopButton = button('Stop', 'Stop growing the plants', 'variants-stop', () => actions.stop());
    this.stopButton.hidden = true;
    const onEnter = (input: HTMLInputElement, go: () => void) => input.addEventListener('keydown', (event) => event.key === 'Enter' && go());
    const makeDefine = () => actions.make('define', this.constant.value, this.values.value);
    const makeSeeds = () => actions.make('seeds', '', this.seeds.value);
    onEnter(this.values, makeDefine);
    onEnter(this.seeds, makeSeeds);
    this.element = el(
      'div',
      { className: 'stages-bar variants-bar' },
      el('span', { className: 'variants-make', title: 'The grammar on screen with one constant at each value' }, 'Vary ', this.constant, ' at ', this.values, button('Make', 'Make the row: the grammar on screen with the constant at each value', 'variants-make-define', makeDefine)),
      el('span', { className: 'variants-make', title: 'The grammar on screen grown with each seed (a row of specimens)' }, 'Seeds ', this.seeds, button('Make', 'Make the row: the grammar on screen grown with each seed', 'variants-make-seeds', makeSeeds)),
      button('+ This grammar', 'Add a copy of the grammar on screen (edit the copy under the figure)', 'variants-add-shown', () => actions.addShown()),
      button('+ Paste', 'Add a plant whose text you paste or type under the figure', 'variants-add-empty', () => actions.add('', 'pasted')),
      this.example,
      this.scaleChoice,
      this.status,
      this.stopButton,
      button('PNG', 'Download the row as one PNG image, each plant captioned', 'variants-png', () => actions.png()),
      button('SVG', 'Download the row as one SVG drawing (each plant projected onto the X–Y plane)', 'variants-svg', () => actions.svg()),
      button('Close', 'Close Variants: the plant on screen again', 'variants-close', () => actions.close()),
    );
    this.element.setAttribute('role', 'group');
    this.element.setAttribute('aria-label', 'Variants');
  }

  /** The constants the grammar on screen offers to vary (none: the choice is disabled). */
  showConstants(names: readonly string[]): void {
    const listed = [...this.constant.options].map((o) => o.value).filter((v) => v !== '');
    const same = listed.length === names.length && listed.every((name, i) => name === names[i]);
    if (same && this.constant.options.length > 0) return; // an open list is left alone
    const chosen = this.constant.value;
    this.constant.replaceChildren(...names.map((name) => el('option', { value: name, textContent: name })));
    if (names.includes(chosen)) this.constant.value = chosen;
    this.constant.disabled = names.length === 0;
    if (names.length === 0) this.constant.append(el('option', { value: '', textContent: 'no constant with a number' }));
  }

  /** The scale chosen. */
  scale(): StageScale {
    return this.scaleChoice.value === 'each' ? 'each' : 'one';
  }

  /** Shows Stop while plants are grown. */
  growing(on: boolean): void {
    this.stopButton.hidden = !on;
  }

  say(state: 'growing' | 'done' | 'error', text: string): void {
    this.status.textContent = text;
    this.status.dataset.state = state;
  }

  private async listExamples(): Promise<void> {
    if (this.examplesListed) return;
    this.examplesListed = true;
    try {
      const entries = await fetchManifest();
      this.example.append(...entries.map((entry) => el('option', { value: entry.file, textContent: entry.title })));
    } catch (error) {
      this.examplesListed = false;
      this.say('error', `Could not list the examples: ${error instanceof Error ? error.message : String(error)}`);
    }
  }

  private async addExample(): Promise<void> {
    const file = this.example.value;
    const title = this.example.selectedOptions[0]?.textContent ?? file;
    this.example.value = '';
    if (!file) return;
    try {
      this.actions.add(await fetchExample(file), title.slice(0, MAX_CAPTION));
    } catch (error) {
      this.say('error', `Could not open the example: ${error instanceof Error ? error.message : String(error)}`);
    }
  }
}
