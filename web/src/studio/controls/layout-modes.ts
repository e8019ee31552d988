// How the studio is laid out for the room it is in: on a narrow screen the plant and the grammar
// take turns (the Grammar / Plant button); Large, for a projector, enlarges the type and gives the
// view most of the screen; Fullscreen shows the plant alone with the derivation's controls; the
// panels under the view fold away. The modes are classes and data attributes on <body> and the
// inspector (styles/layout-modes.css does the layout; styles/presentation-modes.css, loaded on first use, Large and fullscreen); this file keeps them, their buttons and their keys.
import type { KeyValueStorage } from '../../share';

/** The controls (see index.html). */
export interface LayoutElements {
  /** Narrow screens: shows the grammar or the plant. */
  paneToggle: HTMLButtonElement;
  fullscreen: HTMLButtonElement;
  exitViewOnly: HTMLButtonElement;
  large: HTMLButtonElement;
  inspector: HTMLElement;
  inspectorToggle: HTMLButtonElement;
}

/** What the modes need of the studio. */
export interface LayoutHost {
  /** The editor measures its lines again (its font size changed). */
  remeasureEditor(): void;
  /** Large mode was turned on or off (the view draws thicker lines in it). */
  largeChanged?(large: boolean): void;
}

/** Where Large is remembered between visits. */
const LARGE_KEY = 'meristem.large';
/** Below this height the panels under the view start folded. */
const SHORT_SCREEN = '(max-height: 560px)';

export class LayoutModes {
  private readonly body = document.body;
  /** The inspector was folded before Large folded it. */
  private foldedBeforeLarge = false;

  constructor(
    private readonly els: LayoutElements,
    private readonly host: LayoutHost,
    private readonly storage: KeyValueStorage | undefined,
  ) {
    els.paneToggle.addEventListener('click', () => this.showPane(this.body.dataset.pane === 'grammar' ? 'plant' : 'grammar'));
    els.fullscreen.addEventListener('click', () => this.toggleViewOnly());
    els.exitViewOnly.addEventListener('click', () => this.exitViewOnly());
    els.large.addEventListener('click', () => this.setLarge(!this.large));
    els.inspectorToggle.addEventListener('click', () => this.fold(!this.folded));
    document.addEventListener('fullscreenchange', () => {
      if (!document.fullscreenElement && this.viewOnly) this.exitViewOnly();
    });
    document.addEventListener('keydown', (event) => {
      // Without the browser's fullscreen (refused, or in a frame), Escape still leaves.
      if (event.key === 'Escape' && this.viewOnly && !document.fullscreenElement && !event.defaultPrevented) this.exitViewOnly();
    });
    this.showPane('plant');
    this.fold(window.matchMedia(SHORT_SCREEN).matches);
    this.setLarge(storage?.getItem(LARGE_KEY) === '1');
  }

  get large(): boolean {
    return this.body.classList.contains('large');
  }

  get viewOnly(): boolean {
    return this.body.classList.contains('view-only');
  }

  get folded(): boolean {
    return this.els.inspector.hasAttribute('data-collapsed');
  }

  /** On a narrow screen: the plant's pane or the grammar's (a wide screen shows both). */
  showPane(pane: 'plant' | 'grammar'): void {
    this.body.dataset.pane = pane;
    const grammar = pane === 'grammar';
    this.els.paneToggle.textContent = grammar ? 'Plant' : 'Grammar';
    this.els.paneToggle.setAttribute('aria-expanded', String(grammar));
    this.els.paneToggle.title = grammar ? 'Show the plant' : 'Show the grammar (on a narrow screen the plant and the grammar take turns)';
    if (grammar) this.host.remeasureEditor();
  }

  /** Large on or off (remembered in this browser). */
  setLarge(on: boolean): void {
    if (on === this.large) return;
    this.body.classList.toggle('large', on);
    if (on) void presentationStyles().then(() => this.host.remeasureEditor());
    this.els.large.setAttribute('aria-pressed', String(on));
    if (on) {
      this.foldedBeforeLarge = this.folded;
      this.fold(true);
    } else {
      this.fold(this.foldedBeforeLarge);
    }
    try {
      if (on) this.storage?.setItem(LARGE_KEY, '1');
      else this.storage?.removeItem(LARGE_KEY);
    } catch {
      // A full or refused storage only forgets the choice.
    }
    this.host.remeasureEditor();
    this.host.largeChanged?.(on);
  }

  /** The plant alone (and the browser's fullscreen when it allows it), or back. */
  toggleViewOnly(): void {
    if (this.viewOnly) this.exitViewOnly();
    else this.enterViewOnly();
  }

  private enterViewOnly(): void {
    this.body.classList.add('view-only');
    void presentationStyles();
    this.showPane('plant');
    this.els.fullscreen.setAttribute('aria-pressed', 'true');
    // The page is still the studio if the browser refuses (a frame without allowfullscreen).
    document.documentElement.requestFullscreen?.().catch(() => {});
    this.els.exitViewOnly.focus();
  }

  exitViewOnly(): void {
    if (!this.viewOnly) return;
    this.body.classList.remove('view-only');
    this.els.fullscreen.setAttribute('aria-pressed', 'false');
    if (document.fullscreenElement) void document.exitFullscreen().catch(() => {});
    this.els.fullscreen.focus();
  }

  /** Folds the panels under the view (only their tabs stay) or unfolds them. */
  fold(folded: boolean): void {
    this.els.inspector.toggleAttribute('data-collapsed', folded);
    this.els.inspectorToggle.setAttribute('aria-expanded', String(!folded));
    this.els.inspectorToggle.setAttribute('aria-label', folded ? 'Show the string and derivation panels' : 'Hide the string and derivation panels');
  }
}

let presentationLoad: Promise<unknown> | undefined;

/** The presentation modes' CSS (Large, fullscreen), loaded once, the first time one is entered. */
function presentationStyles(): Promise<unknown> {
  return (presentationLoad ??= import('../../styles/presentation-modes.css'));
}
