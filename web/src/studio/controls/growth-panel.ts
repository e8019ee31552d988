// The Growth panel: the particle attributes of seed 002 (lifetime, speed, length and width by age,
// sun, gravity, wind, apices) as switches and fields that read and write the grammar's growth
// directives. Each change is one editor change (undoable), so the plant follows through the normal
// live preview; a value the core would not read is marked and not written.
import { findDirective } from '../../editor/directive-lines';
import {
  argumentValues,
  setArguments,
  toggleAttribute,
  validArgument,
  type GrowthAttribute,
  type TextChange,
} from '../../editor/growth-directives';
import './growth-panel.css';

/** What the panel needs of the editor. */
export interface GrowthEditor {
  text(): string;
  replaceRange(from: number, to: number, insert: string): void;
}

interface Row {
  attribute: GrowthAttribute;
  toggle: HTMLInputElement;
  inputs: (HTMLInputElement | HTMLSelectElement)[];
}

export class GrowthPanel {
  private readonly rows: Row[];

  constructor(
    list: HTMLElement,
    private readonly count: HTMLElement,
    private readonly editor: GrowthEditor,
    attributes: readonly GrowthAttribute[],
  ) {
    this.rows = attributes.map((attribute) => this.row(attribute));
    list.replaceChildren(
      ...this.rows.map((r) => {
        const row = document.createElement('div');
        row.className = 'growth-row';
        row.dataset.directive = r.attribute.directive;
        const label = document.createElement('label');
        label.className = 'growth-toggle';
        label.title = r.attribute.title;
        label.append(r.toggle, ` ${r.attribute.label}`);
        const fields = document.createElement('span');
        fields.className = 'growth-fields';
        r.inputs.forEach((input, i) => {
          const field = document.createElement('label');
          field.className = 'growth-field';
          const { title, label, name } = r.attribute.fields[i];
          field.title = title;
          // The plain words, and the paper's name beside them (`at least MB`).
          const words = Object.assign(document.createElement('span'), { className: 'growth-field-label', textContent: label });
          if (label !== name) words.append(' ', Object.assign(document.createElement('span'), { className: 'growth-abbr', textContent: name }));
          field.append(words, input);
          fields.append(field);
        });
        row.append(label, fields);
        return row;
      }),
    );
  }

  private row(attribute: GrowthAttribute): Row {
    const toggle = Object.assign(document.createElement('input'), { type: 'checkbox' });
    toggle.dataset.testid = `growth-${attribute.directive}`;
    toggle.title = attribute.title;
    const inputs = attribute.fields.map((field) => {
      let input: HTMLInputElement | HTMLSelectElement;
      if (field.kind === 'season') {
        input = document.createElement('select');
        for (const season of field.choices ?? []) input.append(new Option(season, season));
      } else {
        input = Object.assign(document.createElement('input'), { type: 'text', placeholder: field.placeholder ?? '' });
        input.inputMode = field.kind === 'number' ? 'decimal' : 'text';
        input.spellcheck = false;
        input.size = field.kind === 'names' ? 10 : 5;
      }
      input.dataset.testid = `growth-${attribute.directive}-${field.name.replace(/\s+/g, '-').toLowerCase()}`;
      input.setAttribute('aria-label', `${attribute.label}: ${field.label === field.name ? field.name : `${field.label} (${field.name})`}`);
      return input;
    });
    const row: Row = { attribute, toggle, inputs };
    toggle.addEventListener('change', () => this.write(toggleAttribute(this.editor.text(), attribute, toggle.checked)));
    inputs.forEach((input, i) => {
      const check = () => input.setAttribute('aria-invalid', String(!validArgument(attribute.fields[i], input.value)));
      input.addEventListener('input', check);
      input.addEventListener('change', () => {
        check();
        this.write(setArguments(this.editor.text(), attribute, row.inputs.map((x) => x.value)));
      });
    });
    return row;
  }

  private write(change: TextChange | null): void {
    if (change) this.editor.replaceRange(change.from, change.to, change.insert);
  }

  /** Shows the directives of `text` (a field being typed in keeps what is typed). */
  update(text: string): void {
    let on = 0;
    for (const { attribute, toggle, inputs } of this.rows) {
      const found = findDirective(text, attribute.directive);
      toggle.checked = found !== null;
      if (found) on++;
      const values = found ? argumentValues(attribute, found) : attribute.defaults.concat(Array(attribute.fields.length).fill('')).slice(0, attribute.fields.length);
      inputs.forEach((input, i) => {
        input.disabled = found === null;
        if (document.activeElement === input) return;
        input.value = input instanceof HTMLSelectElement ? values[i].toLowerCase() : values[i];
        input.setAttribute('aria-invalid', String(found !== null && !validArgument(attribute.fields[i], input.value)));
      });
    }
    this.count.textContent = on > 0 ? String(on) : '';
  }
}
