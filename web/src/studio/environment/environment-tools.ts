// The View toolbar's Environment tools (issue 47), for a grammar that declares an environment: a
// toggle that shows the environment with the plant (the light grid as a heat-map slice, obstacles,
// attraction points) and a menu to choose the slice (horizontal or vertical) and move it through
// the grid's layers. The tools appear with the first such build and hide for a grammar without
// one; the three.js layer (../../view/environment-layer.ts) loads with the first.
import type { EnvironmentData } from '../../core';
import type { PlantView } from '../../view';
import { closeLikeAMenu } from '../page';

/** The layer's three.js code, loaded with the first environment. */
const layerCode = () => import('../../view/environment-layer');
type LayerCode = Awaited<ReturnType<typeof layerCode>>;
type Layer = InstanceType<LayerCode['EnvironmentLayer']>;
type Axis = 'y' | 'z' | 'none';

/** The toggle and its menu, made here (the first plant's page has none of it). */
function makeTools(): { root: HTMLElement; toggle: HTMLButtonElement; axis: HTMLSelectElement; layer: HTMLInputElement; at: HTMLOutputElement; legend: HTMLElement } {
  const root = document.createElement('span');
  root.className = 'environment-tools';
  root.style.gap = '2px'; // as the toolbar's other groups (its display: see `shown`)
  root.setAttribute('role', 'group');
  root.setAttribute('aria-label', 'Environment');
  root.innerHTML = `
    <button type="button" data-testid="environment" aria-pressed="true" title="Show the environment with the plant: the light grid as a heat map (dark purple: shade, pale yellow: full light), obstacles, attraction points">Environment</button>
    <details class="downloads tool-menu" data-testid="environment-menu">
      <summary aria-label="Environment slice" title="Which slice of the light grid is shown">▾</summary>
      <div class="download-menu">
        <label class="field" title="Slice the grid across (a layer at one height) or upright (a layer at one depth)">
          Slice
          <select data-testid="environment-axis">
            <option value="y">horizontal</option>
            <option value="z">vertical</option>
            <option value="none">none</option>
          </select>
        </label>
        <label class="field" title="Move the slice through the grid's layers">
          Layer
          <input data-testid="environment-layer" type="range" min="0" max="0" step="1" value="0" />
        </label>
        <output data-testid="environment-at"></output>
        <div class="environment-legend" data-testid="environment-legend"></div>
      </div>
    </details>`;
  const get = <T extends Element>(id: string) => root.querySelector(`[data-testid="${id}"]`) as T;
  return {
    root,
    toggle: get<HTMLButtonElement>('environment'),
    axis: get<HTMLSelectElement>('environment-axis'),
    layer: get<HTMLInputElement>('environment-layer'),
    at: get<HTMLOutputElement>('environment-at'),
    legend: get<HTMLElement>('environment-legend'),
  };
}

/** The Environment tools of the studio's view. */
export class EnvironmentTools {
  private tools: ReturnType<typeof makeTools> | undefined;
  private code: Promise<LayerCode> | undefined;
  private layer: Layer | undefined;
  private environment: EnvironmentData | undefined;
  private on = true;
  /** The user moved the slice: new builds keep the layer (else each goes to its liveliest). */
  private chosen = false;
  /**
   * The user chose the slice's axis for plants like the one shown (else horizontal, or vertical
   * for a flat plant, seen face-on); a plant flat where the last was not (or the other way) starts
   * from its own again.
   */
  private axisChosen = false;
  private flat = false;
  /** Bumped by each build shown, so a late layer load draws only the newest. */
  private ticket = 0;

  constructor(private readonly view: PlantView) {}

  /**
   * Shows a build's environment (undefined: the grammar declares none, and the tools hide); `flat`:
   * the plant lies in the plane z = 0 (drawn face-on), where a vertical slice is the one seen.
   */
  show(environment: EnvironmentData | undefined, flat = false): void {
    const ticket = ++this.ticket;
    this.environment = environment;
    if (!environment) {
      if (this.tools) shown(this.tools.root, false);
      if (this.layer) this.view.drawLayer(this.layer.group, false);
      this.view.canvas.parentElement?.removeAttribute('data-environment');
      return;
    }
    const tools = this.ensureTools();
    shown(tools.root, true);
    if (flat !== this.flat) [this.flat, this.axisChosen] = [flat, false];
    if (!this.axisChosen) tools.axis.value = flat ? 'z' : 'y';
    void this.loadLayer().then((layer) => {
      if (ticket === this.ticket) this.draw(layer);
    });
  }

  private ensureTools(): ReturnType<typeof makeTools> {
    if (this.tools) return this.tools;
    const tools = makeTools();
    // In the View toolbar after the Grid toggle; in the view's container when there is no toolbar.
    const container = this.view.canvas.parentElement;
    const toolbar = container?.closest('.view-column')?.querySelector('.view-tools');
    const grid = toolbar?.querySelector('[data-testid="grid"]');
    if (grid) grid.after(tools.root);
    else (toolbar ?? container ?? document.body).append(tools.root);
    closeLikeAMenu(tools.root.querySelector('details')!);
    tools.toggle.addEventListener('click', () => {
      this.on = !this.on;
      if (this.layer) this.draw(this.layer);
    });
    tools.axis.addEventListener('change', () => {
      this.axisChosen = true;
      this.chosen = false; // the other axis: its liveliest layer first
      if (this.layer) this.draw(this.layer);
    });
    tools.layer.addEventListener('input', () => {
      this.chosen = true;
      if (!this.layer) return;
      this.layer.setSlice(tools.axis.value as Axis, Number(tools.layer.value));
      this.showLayer(this.layer);
    });
    return (this.tools = tools);
  }

  private loadLayer(): Promise<Layer> {
    this.code ??= layerCode();
    this.code.catch(() => (this.code = undefined)); // the next build tries again
    return this.code.then((code) => {
      this.layer ??= new code.EnvironmentLayer();
      return this.layer;
    });
  }

  /** Draws the environment on the layer as the tools say. */
  private draw(layer: Layer): void {
    const tools = this.tools!;
    layer.show(this.environment);
    const axis = tools.axis.value as Axis;
    const field = layer.sliced;
    layerCode()
      .then(({ heatColour, heatRange, layersOf, liveliestLayer }) => {
        tools.legend.replaceChildren(...(field ? [legend(heatColour, heatRange(field))] : []));
        const layers = layersOf(field, axis);
        const wanted = this.chosen || !field || axis === 'none' ? Number(tools.layer.value) : liveliestLayer(field, axis);
        tools.layer.max = String(Math.max(0, layers - 1));
        tools.layer.disabled = layers === 0;
        layer.setSlice(axis, wanted);
        this.showLayer(layer);
      })
      .catch((error: unknown) => console.error('The environment could not be drawn:', error));
  }

  /** Puts the layer on screen (or takes it off) and says what it shows. */
  private showLayer(layer: Layer): void {
    const tools = this.tools!;
    const field = layer.sliced;
    const axis = tools.axis.value as Axis;
    tools.layer.value = String(layer.layerShown);
    tools.toggle.setAttribute('aria-pressed', String(this.on));
    tools.at.textContent = field && axis !== 'none' ? sliceWords(field, axis, layer.layerShown) : field ? '' : 'No light grid (declare #environment light and write ?E)';
    this.view.drawLayer(layer.group, this.on);
    const container = this.view.canvas.parentElement;
    if (container) container.dataset.environment = this.on ? `${axis}:${layer.layerShown}` : 'off';
  }
}

/** Shows or hides the tools (an inline style, which `hidden` would not override). */
function shown(root: HTMLElement, on: boolean): void {
  root.style.display = on ? 'inline-flex' : 'none';
  root.toggleAttribute('hidden', !on);
}

/** Where a slice is, in words: `height y = 2.5 (layer 4 of 12)`. */
export function sliceWords(field: { origin: number[]; cell: number; dims: number[] }, axis: 'y' | 'z', layer: number): string {
  const i = axis === 'y' ? 1 : 2;
  const at = field.origin[i] + (layer + 0.5) * field.cell;
  const where = axis === 'y' ? 'height y' : 'depth z';
  return `${where} = ${Number(at.toPrecision(4))} (layer ${layer + 1} of ${field.dims[i]})`;
}

/** The heat map's legend: its colours from the grid's least value (shade) to its most (light). */
function legend(heatColour: (value: number) => [number, number, number], [lo, hi]: [number, number]): DocumentFragment {
  const fragment = document.createDocumentFragment();
  const ramp = document.createElement('span');
  ramp.className = 'environment-ramp';
  const stops = [0, 0.25, 0.5, 0.75, 1].map((v) => `rgb(${heatColour(v).join(' ')}) ${v * 100}%`);
  ramp.style.cssText = 'display: inline-block; width: 8em; height: 0.8em; margin: 0 0.4em; vertical-align: middle; border-radius: 2px';
  ramp.style.background = `linear-gradient(to right, ${stops.join(', ')})`;
  const number = (x: number) => String(Number(x.toFixed(2)));
  const [dark, light] = [`shade ${number(lo)}`, `${number(hi)} light`].map((text) => {
    const span = document.createElement('span');
    span.textContent = text;
    return span;
  });
  fragment.append(dark, ramp, light);
  return fragment;
}
