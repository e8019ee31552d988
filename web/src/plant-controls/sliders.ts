// A slider for every `#define` constant with a plain number (as in vlab's control panels):
// dragging rewrites the number in the text (one undo step per drag) and the plant follows. The
// range is the one in a `// [min, max]` comment, else the default of editor/defines.ts, which
// stays put while the number is one the slider wrote (so a drag does not rescale its own slider)
// and follows the number when the text gives another (typed, pasted, an opened file: issue 50,
// finding 15: `#define a 1000` then a pasted `#define a 0.5` kept [0, 2000] and step 1).
import { defineConstants, formatNumber, type DefineConstant } from '../editor/defines';

/** A slider's range and step. */
export interface SliderRange {
  min: number;
  max: number;
  step: number;
}

/** The range a constant's slider showed, and the number (as written) it showed it for. */
export interface RememberedRange {
  range: SliderRange;
  /** The number the range is kept for: the last one shown, or the last one the slider wrote. */
  text: string;
}

/**
 * The range each constant's slider shows: its written range if it has one; else the range it
 * had before (`remembered`, by name) while the number is the one it had then or the one its
 * slider wrote ({@link SliderPanel}); else (another number: typed, pasted, opened) the default
 * of the number now in the text, with its step. `remembered` is updated.
 */
export function sliderRanges(constants: readonly DefineConstant[], remembered: Map<string, RememberedRange>): SliderRange[] {
  return constants.map((c) => {
    const fresh = { min: c.min, max: c.max, step: c.step };
    const old = remembered.get(c.name);
    if (!c.ranged && old && old.text === c.text && c.value >= old.range.min && c.value <= old.range.max) return old.range;
    remembered.set(c.name, { range: fresh, text: c.text });
    return fresh;
  });
}

/** What the panel needs of the editor. */
export interface SliderEditor {
  replaceRange(from: number, to: number, insert: string, options?: { history?: boolean }): void;
}

/** The sliders of the constants panel; call {@link SliderPanel.update} with the text on every change. */
export class SliderPanel {
  private constants: DefineConstant[] = [];
  private ranges: SliderRange[] = [];
  private readonly remembered = new Map<string, RememberedRange>();
  private rows: { row: HTMLElement; input: HTMLInputElement; output: HTMLOutputElement }[] = [];
  private layout = '';
  /** The slider being dragged and its number as written when the drag began. */
  private drag: { index: number; text: string } | undefined;

  /**
   * @param list where the slider rows go
   * @param count where the number of constants is shown (the panel's summary)
   * @param empty the hint shown when there are no constants
   */
  constructor(
    private readonly list: HTMLElement,
    private readonly count: HTMLElement,
    private readonly empty: HTMLElement,
    private readonly editor: SliderEditor,
  ) {}

  /** The value of every slider, by its constant's name (what a share link records). */
  values(): Record<string, number> {
    return Object.fromEntries(this.constants.map((c) => [c.name, c.value]));
  }

  /** Forgets the remembered ranges (another grammar was opened). */
  reset(): void {
    this.remembered.clear();
  }

  /** Shows the constants of `text`; rows are rebuilt only when names or ranges change. */
  update(text: string): void {
    this.constants = defineConstants(text);
    this.ranges = sliderRanges(this.constants, this.remembered);
    const layout = JSON.stringify(this.constants.map((c, i) => [c.name, this.ranges[i]]));
    if (layout !== this.layout) {
      this.layout = layout;
      this.render();
    }
    for (const [i, c] of this.constants.entries()) {
      const { input, output } = this.rows[i];
      if (Number(input.value) !== c.value) input.value = String(c.value);
      output.value = c.text;
      input.setAttribute('aria-valuetext', c.text);
    }
    this.count.textContent = this.constants.length > 0 ? String(this.constants.length) : '';
    this.empty.hidden = this.constants.length > 0;
  }

  private render(): void {
    this.rows = this.constants.map((c, i) => {
      const range = this.ranges[i];
      const id = `define-${i}-${c.name}`;
      const row = document.createElement('div');
      row.className = 'slider-row';
      const label = document.createElement('label');
      label.htmlFor = id;
      label.textContent = c.name;
      label.title = c.ranged ? `#define ${c.name}, range from its comment` : `#define ${c.name}; set the range with a comment: // [min, max]`;
      const input = document.createElement('input');
      input.type = 'range';
      input.id = id;
      input.dataset.define = c.name;
      input.min = String(range.min);
      input.max = String(range.max);
      input.step = String(range.step);
      input.value = String(c.value);
      input.addEventListener('input', () => this.moved(i, Number(input.value)));
      input.addEventListener('change', () => this.released(i));
      const output = document.createElement('output');
      output.htmlFor.add(id);
      const bounds = document.createElement('span');
      bounds.className = 'slider-bounds';
      bounds.textContent = `${formatNumber(range.min, range.step)} … ${formatNumber(range.max, range.step)}`;
      row.append(label, input, output, bounds);
      return { row, input, output };
    });
    this.list.replaceChildren(...this.rows.map((r) => r.row));
  }

  /**
   * Writes slider `index`'s new value into the text at once (the plant follows), outside the undo
   * history: the drag becomes one undo step when it ends ({@link released}).
   */
  private moved(index: number, value: number): void {
    const constant = this.constants[index];
    if (!constant) return;
    const text = formatNumber(value, this.ranges[index].step);
    if (text === constant.text) return;
    if (this.drag?.index !== index) this.drag = { index, text: constant.text };
    this.keepRange(index, text);
    this.editor.replaceRange(constant.from, constant.to, text, { history: false });
  }

  /** The drag (or key press) ended: one undo step from the value before it to the value now. */
  private released(index: number): void {
    const drag = this.drag;
    this.drag = undefined;
    const constant = this.constants[index];
    if (!drag || drag.index !== index || !constant || drag.text === constant.text) return;
    const final = constant.text;
    this.keepRange(index, drag.text);
    this.editor.replaceRange(constant.from, constant.to, drag.text, { history: false });
    const restored = this.constants[index];
    this.keepRange(index, final);
    this.editor.replaceRange(restored.from, restored.to, final);
  }

  /** The slider is writing `text` for constant `index`: its range stays when the text comes back. */
  private keepRange(index: number, text: string): void {
    const constant = this.constants[index];
    const remembered = constant && this.remembered.get(constant.name);
    if (remembered) remembered.text = text;
  }
}
