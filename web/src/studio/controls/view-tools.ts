// The view tools (index.html, above the 3D view, and the "Colour by production" switch): controls
// of the view options. They change the ViewOptions and render from it: a toggle's `aria-pressed`,
// a field's value are its output, never read back as state. The 3D view follows the options here.
import { lineWidthOf, type PlantView } from '../../view';
import { closeLikeAMenu } from '../page';
import type { ViewOption, ViewOptions, ViewOptionValues } from './view-options';

/** The controls (see index.html). */
export interface ViewToolElements {
  frame: HTMLButtonElement;
  /** The 2D toggle: pressed while the view is orthographic (chosen, or automatic for a flat plant). */
  projection: HTMLButtonElement;
  /** The Lines toggle: pressed while branches are lines (chosen, or automatic for a flat plant). */
  renderLines: HTMLButtonElement;
  /** The lines' width in pixels. */
  lineWidth: HTMLInputElement;
  grid: HTMLButtonElement;
  lighting: HTMLButtonElement;
  textures: HTMLButtonElement;
  sides: HTMLSelectElement;
  smoothAll: HTMLInputElement;
  byProduction: HTMLInputElement;
  /** The toolbar's menus (framing, tubes): they close like menus. */
  menus: HTMLDetailsElement[];
  /** The tools of the 3D view of one plant (framing, 2D, grid, textures, branch editing): paused during Stages. */
  plantOnly: HTMLElement[];
}

/** The toggle buttons, by the option each one switches. */
type ToggleOption = 'grid' | 'lighting' | 'textures';
const TOGGLES: readonly ToggleOption[] = ['grid', 'lighting', 'textures'];

/** The numbers of sides a `<select>` offers. */
export function sidesChoices(select: HTMLSelectElement): number[] {
  return [...select.options].map((option) => Number(option.value));
}

/** Connects the controls and the 3D view to the view options. */
export class ViewTools {
  constructor(
    private readonly els: ViewToolElements,
    private readonly options: ViewOptions,
    private readonly view: PlantView,
  ) {
    els.frame.addEventListener('click', () => view.frame());
    els.menus.forEach(closeLikeAMenu);
    els.projection.addEventListener('click', () => this.toggleProjection());
    els.renderLines.addEventListener('click', () => this.toggleLines());
    els.lineWidth.addEventListener('change', () => {
      const width = lineWidthOf(els.lineWidth.value);
      if (width === null) els.lineWidth.value = String(options.values.lineWidth); // refused: back to the one in force
      else options.set({ lineWidth: width });
    });
    for (const option of TOGGLES) els[option].addEventListener('click', () => options.set({ [option]: !options.values[option] }));
    els.sides.addEventListener('change', () => options.set({ sides: Number(els.sides.value) }));
    els.smoothAll.addEventListener('change', () => options.set({ smoothAll: els.smoothAll.checked }));
    els.byProduction.addEventListener('change', () => options.set({ byProduction: els.byProduction.checked }));
    options.onChange((values, changed) => this.show(values, changed));
    this.show(options.values, new Set(Object.keys(options.values) as ViewOption[]));
  }

  /** Switches between 2D and 3D: the projection other than the one on screen, fixed. */
  toggleProjection(): void {
    this.options.set({ projection: this.view.projection === 'orthographic' ? 'perspective' : 'orthographic' });
  }

  /** Switches between lines and tubes: the mode other than the one on screen, fixed. */
  toggleLines(): void {
    this.options.set({ render: this.view.usesLines ? 'tubes' : 'lines' });
  }

  /** Stages covers the 3D view (`on`) or not: the tools that act on it pause meanwhile. */
  pauseForStages(on: boolean): void {
    for (const tool of this.els.plantOnly) {
      tool.inert = on;
      tool.classList.toggle('paused', on);
    }
  }

  /** Shows the projection in use on the 2D toggle (call after each plant: `auto` follows it). */
  showProjection(): void {
    this.els.projection.setAttribute('aria-pressed', String(this.view.projection === 'orthographic'));
    this.els.renderLines.setAttribute('aria-pressed', String(this.view.usesLines));
  }

  /** Brings the view and the controls in step with the options that changed. */
  private show(values: Readonly<ViewOptionValues>, changed: ReadonlySet<ViewOption>): void {
    const { els, view } = this;
    if (changed.has('grid')) view.setGridVisible(values.grid);
    if (changed.has('lighting')) view.setLighting(values.lighting);
    if (changed.has('textures')) view.setTextures(values.textures);
    if (changed.has('projection')) view.setProjectionMode(values.projection);
    if (changed.has('render')) view.setRenderMode(values.render);
    if (changed.has('lineWidth')) view.setLineWidth(values.lineWidth);
    els.lineWidth.value = String(values.lineWidth);
    for (const option of TOGGLES) els[option].setAttribute('aria-pressed', String(values[option]));
    els.sides.value = String(values.sides);
    els.smoothAll.checked = values.smoothAll;
    els.byProduction.checked = values.byProduction;
    this.showProjection();
  }
}
