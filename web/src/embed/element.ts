// <meristem-plant>: a live plant for a course page, loaded with one script from the deployed site:
//
//   <script type="module" src="https://…/meristem-plant.js"></script>
//   <meristem-plant src="fern.lsys" iterations="5" controls="iterations, sliders"></meristem-plant>
//   <meristem-plant src="fern.lsys" animate loop speed="1"></meristem-plant>
//
// The grammar is the file at `src` (relative to the page) or, without `src`, the element's own
// text. `iterations` and `seed` override the grammar's; `controls` lists the controls shown
// (`iterations`: − n + and Play; `sliders`: one per `#define`). `animate` plays the growth in time
// at once (`loop`: again and again; `speed`: steps per second; `t`: the time to start from; `from`
// and `to`: the range played), as Play does on demand; a timed grammar (`#terminal_age`) is
// derived at each time shown, as the studio's timeline does. Every plant of the page builds in
// one shared worker; the textures and the studio link point at the site this script came from.
// The plant's box (`.mp`, in the shadow root) says what is shown, for the page's scripts and
// tests: `data-state` (ok, error), `data-iterations`, `data-modules`, `data-bounds` (min x y z,
// max x y z) and `data-t` (the growth time shown).
import { loadVocabulary } from '../core';
import { EmbedPlant, GROWTH_ATTRIBUTES, growthAttributes, parseControls, wholeAttribute } from './embed-plant';
import { EMBED_CSS } from './embed-style';
import { sharedBuilds } from './shared-builds';

/**
 * Where this script (and the studio) is: the site's root. (So embed/ has no index.ts: vite would
 * read `new URL('./', import.meta.url)` as that file and inline it.)
 */
const SITE_ROOT = new URL('./', import.meta.url).href;

/**
 * Why a grammar at `url`, on another site than the page, could not be read: most often its server
 * does not let other sites' pages read it (CORS), which the browser tells only its console.
 */
export function crossOrigin(url: URL): string {
  return (
    `${url.href} is on another site (${url.host}), and its server did not let this page read it. ` +
    'Its server must send the header “Access-Control-Allow-Origin” (e.g. “Access-Control-Allow-Origin: *”) with the grammar, ' +
    'or put the grammar on this page’s own site, or write it inside the element: <meristem-plant>axiom: F …</meristem-plant>.'
  );
}

export class MeristemPlantElement extends HTMLElement {
  static readonly observedAttributes = ['src', 'iterations', 'seed', 'controls', ...GROWTH_ATTRIBUTES];
  private plant: EmbedPlant | undefined;
  /** Bumped on every (re)load, so a slow fetch of an old `src` is dropped. */
  private loads = 0;

  connectedCallback(): void {
    if (!this.shadowRoot) {
      const shadow = this.attachShadow({ mode: 'open' });
      const style = document.createElement('style');
      style.textContent = EMBED_CSS;
      shadow.append(style);
    }
    void this.load();
  }

  disconnectedCallback(): void {
    this.loads++;
    this.plant?.dispose();
    this.plant = undefined;
  }

  attributeChangedCallback(): void {
    if (this.isConnected && this.shadowRoot) void this.load();
  }

  /** The grammar: the file at `src`, or the element's text. */
  private async grammar(): Promise<string> {
    const src = this.getAttribute('src');
    if (!src) return this.textContent?.trim() ?? '';
    const url = new URL(src, document.baseURI);
    const response = await fetch(url).catch((error: unknown) => {
      throw url.origin === location.origin ? error : new Error(crossOrigin(url));
    });
    if (!response.ok) throw new Error(`${src}: HTTP ${response.status}`);
    return response.text();
  }

  private async load(): Promise<void> {
    const load = ++this.loads;
    const controls = parseControls(this.getAttribute('controls'));
    let source: string;
    try {
      [source] = await Promise.all([this.grammar(), controls.has('sliders') ? loadVocabulary() : Promise.resolve()]);
    } catch (error) {
      if (load === this.loads) this.fail(`Could not load the plant: ${error instanceof Error ? error.message : String(error)}`);
      return;
    }
    if (load !== this.loads || !this.shadowRoot) return;
    this.plant?.dispose();
    this.shadowRoot.querySelector('.mp-failed')?.remove();
    const iterations = wholeAttribute('iterations', this.getAttribute('iterations'));
    const seed = wholeAttribute('seed', this.getAttribute('seed'));
    this.plant = new EmbedPlant(this.shadowRoot, {
      source,
      iterations: iterations.value,
      seed: seed.value,
      notes: [iterations.problem, seed.problem].filter((p): p is string => p !== undefined),
      controls,
      growth: growthAttributes(this),
      siteRoot: SITE_ROOT,
      builds: sharedBuilds(),
    });
  }

  private fail(message: string): void {
    this.plant?.dispose();
    this.plant = undefined;
    const note = document.createElement('p');
    note.className = 'mp-failed';
    note.setAttribute('role', 'status');
    note.textContent = message;
    this.shadowRoot?.querySelector('.mp-failed')?.remove();
    this.shadowRoot?.append(note);
  }
}

if (!customElements.get('meristem-plant')) customElements.define('meristem-plant', MeristemPlantElement);

declare global {
  interface HTMLElementTagNameMap {
    'meristem-plant': MeristemPlantElement;
  }
}
