// The Share dialog's "Embed it in a course page": the HTML that puts the plant on screen into
// another page, as an <iframe> of embed.html (the state in its fragment, as a share link) or as a
// <meristem-plant> element with the grammar written in the page. The site's address is the
// studio's own, so the snippets work wherever the studio is deployed. A state with variants
// frames the studio itself, which opens with the Variants view (cameras linked), or writes one
// <meristem-plant> per variant in a row, each captioned.
import type { SharedGrowth, SharedState, SharedVariant } from '../../share';

/** Which controls the embedded plant shows (embed-plant.ts's names). */
export interface SnippetControls {
  iterations: boolean;
  sliders: boolean;
}

function controlList(controls: SnippetControls): string {
  return [controls.iterations && 'iterations', controls.sliders && 'sliders'].filter(Boolean).join(',');
}

/** Text as HTML text (the grammar inside the element): `&`, `<`, `>` escaped. */
function htmlText(text: string): string {
  return text.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
}

/** An attribute value in double quotes. */
function attribute(value: string): string {
  return `"${value.replace(/&/g, '&amp;').replace(/"/g, '&quot;')}"`;
}

/**
 * The growth's attributes (and embed.html's query parameters) for a link's timeline: the plant
 * grows at once (`animate`), looped, at the speed and over the range the timeline had. None
 * when the timeline was not used.
 */
export function growthParameters(growth: SharedGrowth | undefined): [string, string | null][] {
  if (growth?.t === undefined) return [];
  const parameters: [string, string | null][] = [['animate', null]];
  if (growth.loop) parameters.push(['loop', null]);
  if (growth.speed !== undefined && growth.speed !== 1) parameters.push(['speed', String(growth.speed)]);
  if (growth.from) parameters.push(['from', String(growth.from)]);
  if (growth.to !== undefined) parameters.push(['to', String(growth.to)]);
  return parameters;
}

/**
 * An <iframe> of embed.html showing `fragment`'s state (`#s=…`), 640 × 480, fullscreen allowed;
 * growing as the timeline did (`growth`, see {@link growthParameters}).
 */
export function frameSnippet(siteRoot: string, fragment: string, controls: SnippetControls, growth?: SharedGrowth, variants = false): string {
  if (variants) {
    const studio = new URL(`./${fragment}`, siteRoot).href;
    return `<iframe src=${attribute(studio)} width="960" height="640" style="border: 0; max-width: 100%" title="Plants side by side, made with Meristem" allowfullscreen loading="lazy"></iframe>`;
  }
  const list = controlList(controls);
  const query = [...(list ? [`controls=${list}`] : []), ...growthParameters(growth).map(([name, value]) => (value === null ? name : `${name}=${value}`))].join('&');
  const src = new URL(`embed.html${query ? `?${query}` : ''}${fragment}`, siteRoot).href;
  return `<iframe src=${attribute(src)} width="640" height="480" style="border: 0; max-width: 100%" title="A plant made with Meristem" allowfullscreen loading="lazy"></iframe>`;
}

/** The script that defines <meristem-plant>, then one element with `state`'s grammar as its text. */
export function elementSnippet(siteRoot: string, state: Pick<SharedState, 'text' | 'iterations' | 'seed' | 'growth' | 'variants'>, controls: SnippetControls): string {
  const script = new URL('meristem-plant.js', siteRoot).href;
  if (state.variants) return variantsSnippet(script, state.variants, controls);
  const list = controlList(controls);
  const attributes = [
    state.iterations === undefined ? '' : ` iterations="${state.iterations}"`,
    state.seed === undefined ? '' : ` seed="${state.seed}"`,
    list ? ` controls="${list}"` : '',
    ...growthParameters(state.growth).map(([name, value]) => (value === null ? ` ${name}` : ` ${name}="${value}"`)),
  ].join('');
  return `<script type="module" src=${attribute(script)}></script>\n<meristem-plant${attributes} style="height: 420px">\n${htmlText(state.text.trimEnd())}\n</meristem-plant>`;
}

/** The script, then a row of one captioned <meristem-plant> per variant (a row of specimens in the page). */
function variantsSnippet(script: string, variants: readonly SharedVariant[], controls: SnippetControls): string {
  const list = controlList(controls);
  const plants = variants.map((v, i) => {
    const attributes = [v.iterations === undefined ? '' : ` iterations="${v.iterations}"`, v.seed === undefined ? '' : ` seed="${v.seed}"`, list ? ` controls="${list}"` : ''].join('');
    const caption = htmlText(v.caption?.trim() || `plant ${i + 1}`);
    return `  <figure style="flex: 1 1 200px; margin: 0">\n    <meristem-plant${attributes} style="height: 360px">\n${htmlText(v.text.trimEnd())}\n    </meristem-plant>\n    <figcaption style="text-align: center">${caption}</figcaption>\n  </figure>`;
  });
  return `<script type="module" src=${attribute(script)}></script>\n<div style="display: flex; flex-wrap: wrap; gap: 8px">\n${plants.join('\n')}\n</div>`;
}

/** The dialog's embed section (see index.html). */
export interface EmbedSnippetElements {
  iterations: HTMLInputElement;
  sliders: HTMLInputElement;
  frame: HTMLTextAreaElement;
  element: HTMLTextAreaElement;
  copyFrame: HTMLButtonElement;
  copyElement: HTMLButtonElement;
  status: HTMLElement;
}

export class EmbedSnippets {
  private shown: { state: SharedState; fragment: string } | undefined;

  constructor(
    private readonly els: EmbedSnippetElements,
    /** The studio's folder: where embed.html and meristem-plant.js are. */
    private readonly siteRoot: string,
  ) {
    for (const box of [els.iterations, els.sliders]) box.addEventListener('change', () => this.render());
    els.copyFrame.addEventListener('click', () => void this.copy(els.frame, 'The frame'));
    els.copyElement.addEventListener('click', () => void this.copy(els.element, 'The element'));
  }

  /** Shows the snippets of `state` (`fragment`: its share link's `#s=…`). */
  show(state: SharedState, fragment: string): void {
    this.shown = { state, fragment };
    this.els.status.textContent = '';
    this.render();
  }

  private render(): void {
    if (!this.shown) return;
    const controls = { iterations: this.els.iterations.checked, sliders: this.els.sliders.checked };
    this.els.frame.value = frameSnippet(this.siteRoot, this.shown.fragment, controls, this.shown.state.growth, this.shown.state.variants !== undefined);
    this.els.element.value = elementSnippet(this.siteRoot, this.shown.state, controls);
  }

  private async copy(area: HTMLTextAreaElement, what: string): Promise<void> {
    area.select();
    try {
      await navigator.clipboard.writeText(area.value);
      this.els.status.textContent = `${what} is on the clipboard.`;
    } catch {
      this.els.status.textContent = 'Select the text and copy it (Ctrl+C).';
    }
  }
}
