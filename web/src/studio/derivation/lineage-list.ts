// The debugger's lineage (issue 48): for the module picked in the plant, its ancestor at every step
// back to the axiom and the production that made each, asked of the core in the build worker.
// Hovering (or focusing) a row lights up in the plant every module that descends from that
// ancestor and marks its production in the editor; the derivation view marks the chain.
import type { LineageRow, PlantInspector, ProductionInfo } from '../../core';
import './lineage-list.css';

/** What the list asks of the view around it. */
export interface LineageHost {
  /** `rule 2 (line 8: F -> FF)`. */
  describeProduction(index: number): string;
  /** Lights up `modules` of the derived string and marks `production` (null: the focus's own highlight again). */
  preview(modules: Iterable<number> | null, production: number | null): void;
}

/**
 * The lineage on screen, for the Derivation tab, which outlines its chain: both load after the
 * first plant, so they meet here rather than through the first plant's script.
 */
export const lineageShown = {
  rows: null as readonly LineageRow[] | null,
  listeners: new Set<(rows: readonly LineageRow[] | null) => void>(),
  tell(rows: readonly LineageRow[] | null): void {
    this.rows = rows;
    for (const listener of this.listeners) listener(rows);
  },
};

/**
 * A lineage as the command line prints it (`meristem lineage FILE MODULE`), one line per step,
 * the last first: `step 2: X [7] <- 7:1 X -> F[+X]F[-X]+X`, `copied`, `axiom`.
 */
export function lineageText(rows: readonly LineageRow[], source: string, productions: readonly ProductionInfo[]): string {
  return rows
    .map((row) => {
      const when = row.time === undefined ? '' : ` (t = ${row.time})`;
      const p = row.production === undefined ? undefined : productions[row.production];
      const how = p ? `${lineColumn(source, p.from)} ${source.slice(p.from, p.to).trim()}` : row.step === 0 ? 'axiom' : 'copied';
      return `step ${row.step}${when}: ${row.text} [${row.module}] <- ${how}\n`;
    })
    .join('');
}

/** `line:column` of a UTF-16 offset, both from 1, the column in characters (as the core counts). */
function lineColumn(source: string, offset: number): string {
  const before = source.slice(0, offset);
  const start = before.lastIndexOf('\n') + 1;
  return `${before.split('\n').length}:${[...before.slice(start)].length + 1}`;
}

/** The list under the summary of the String tab. */
export class LineageList {
  readonly element = document.createElement('section');
  private readonly list = document.createElement('ol');
  private readonly heading = document.createElement('p');
  private ticket = 0;

  constructor(private readonly host: LineageHost) {
    this.element.className = 'lineage';
    this.element.dataset.testid = 'lineage';
    this.element.setAttribute('aria-label', 'Lineage of the picked module');
    this.element.hidden = true;
    this.heading.className = 'lineage-heading';
    this.element.append(this.heading, this.list);
    const leave = () => this.host.preview(null, null);
    this.list.addEventListener('pointerleave', (event) => event.pointerType !== 'touch' && leave());
    this.list.addEventListener('focusout', (event) => !this.list.contains(event.relatedTarget as Node | null) && leave());
  }

  /** Shows the lineage of module `module` (null: hides it), asked of `inspector`. */
  async show(inspector: PlantInspector | undefined, module: number | null, source: string, productions: readonly ProductionInfo[]): Promise<void> {
    const ticket = ++this.ticket;
    if (module === null || !inspector) return this.clear();
    this.heading.textContent = `Lineage of module ${module}: working…`;
    this.element.hidden = false;
    const lineage = await inspector.lineage(module);
    if (ticket !== this.ticket) return;
    if ('error' in lineage) {
      this.list.replaceChildren();
      this.heading.textContent = lineage.error ? `No lineage: ${lineage.error}` : '';
      this.element.hidden = !lineage.error;
      lineageShown.tell(null);
      return;
    }
    const rows = lineage.rows;
    this.element.dataset.text = lineageText(rows, source, productions);
    this.heading.textContent = `Lineage of module ${module}, back to the axiom (hover a step to see all that grew from it):`;
    this.list.replaceChildren(...rows.map((row) => this.item(row)));
    lineageShown.tell(rows);
  }

  /** Hides the list. */
  clear(): void {
    this.ticket++;
    this.element.hidden = true;
    this.list.replaceChildren();
    delete this.element.dataset.text;
    lineageShown.tell(null);
  }

  private item(row: LineageRow): HTMLElement {
    const item = document.createElement('li');
    const button = document.createElement('button');
    button.type = 'button';
    button.dataset.step = String(row.step);
    button.dataset.module = String(row.module);
    if (row.production !== undefined) button.dataset.production = String(row.production);
    const when = row.time === undefined ? `step ${row.step}` : `step ${row.step} (t = ${row.time})`;
    const code = document.createElement('code');
    code.textContent = row.text;
    const how = row.production !== undefined ? `written by ${this.host.describeProduction(row.production)}` : row.step === 0 ? 'in the axiom' : 'copied';
    button.append(`${when}: `, code, ` (module ${row.module}) ${how}`);
    const descendants = row.last - row.first + 1;
    button.title = `${descendants} module${descendants === 1 ? '' : 's'} of the derived string grew from it`;
    const light = () => this.host.preview(range(row.first, row.last), row.production ?? null);
    button.addEventListener('pointerenter', light);
    button.addEventListener('focus', light);
    item.append(button);
    return item;
  }
}

/** first, first + 1, …, last. */
function range(first: number, last: number): number[] {
  return Array.from({ length: Math.max(0, last - first + 1) }, (_, k) => first + k);
}
