// The derivation's controls in the toolbar: the iterations (the box, step −/+) and the seed (the
// box, reroll); the toolbar's Play plays the growth in time (../timeline). Empty boxes mean the grammar's own `#iterations` and `#seed`. A number in
// the iterations box overrides the grammar's, and shows it: the box is marked "overrides N" with a ×
// that clears it (empty, its placeholder is the grammar's value); it is cleared when another text
// is opened or the grammar's own iterations line is edited, and the errors its value causes (the
// step and module limits) are told in the notice bar, since the text has nothing to mark for them.
import { directiveOfKind, languageVocabulary, type DiagnosticList, type PlantBuild } from '../../core';
import { findDirective } from '../../editor/directive-lines';
import type { SharedState } from '../../share';
import type { Notice } from '../page';
import { Playback } from '../../plant-controls';

/** The controls (see index.html). */
export interface DerivationElements {
  iterations: HTMLInputElement;
  /** Around the iterations box: `data-override` when it holds a number. */
  iterationsBox: HTMLElement;
  /** The box's mark while it overrides: "overrides N". */
  iterationsTag: HTMLElement;
  /** The × that clears the override. */
  iterationsReset: HTMLButtonElement;
  stepBack: HTMLButtonElement;
  stepForward: HTMLButtonElement;
  seed: HTMLInputElement;
  reroll: HTMLButtonElement;
}

/** The derivation's overrides as a share link holds them. */
export type SharedDerivation = Pick<SharedState, 'iterations' | 'seed'>;

/** A whole number typed into `input` (0 or more), or undefined when it is empty or not one. */
function wholeNumber(input: HTMLInputElement): number | undefined {
  const value = input.valueAsNumber;
  return Number.isFinite(value) && value >= 0 ? Math.floor(value) : undefined;
}

/**
 * Errors that a number of iterations causes, whose spans the text cannot show for the box: more
 * iterations than the step limit (E0202), and the module limit hit (E0400; docs/LANGUAGE.md).
 */
const ITERATION_ERRORS: ReadonlySet<string> = new Set(['E0202', 'E0400']);

/** The notice's topic for the override's errors. */
const OVERRIDE_TOPIC = 'iterations';

/**
 * What the notice bar says about a build made with the box's `override` of the grammar's
 * iterations: the errors that number causes (the core's messages), or null when there are none.
 */
export function overrideErrors(override: number | undefined, grammarIterations: number, diagnostics: DiagnosticList): { message: string; items: string[] } | null {
  if (override === undefined) return null;
  const errors = diagnostics.where((severity, code) => severity === 'error' && ITERATION_ERRORS.has(code)).slice();
  if (errors.length === 0) return null;
  return {
    message: `${override} iterations, from the Iterations box (the grammar's own: ${grammarIterations}), are too many:`,
    items: errors.map((d) => `${d.code}: ${d.message}`),
  };
}

/** The arguments of the grammar's iterations line as written, or null without one. */
function writtenIterations(text: string): string | null {
  const directive = directiveOfKind(languageVocabulary(), 'Iterations');
  return findDirective(text, directive.name)?.args.join(' ') ?? null;
}

/** The iterations and seed the user asked for, and stepping over the iterations. */
export class DerivationControls {
  /** Step −/+ over the iterations (a build each; Play plays the growth in time instead). */
  readonly playback: Playback;
  /** The grammar's `#iterations` of the last build shown. */
  private grammarIterations = 0;
  /** The grammar's iterations line as last seen in the text (undefined: not seen yet). */
  private iterationsLine: string | null | undefined;
  private readonly listeners = new Set<() => void>();
  /** The last build said the box's number is too many (the step or module limit). */
  private tooMany = false;

  /** `notice` tells the errors the box's value causes. */
  constructor(
    private readonly els: DerivationElements,
    private readonly notice?: Notice,
  ) {
    this.playback = new Playback(
      {
        shown: () => this.iterations() ?? this.grammarIterations,
        grammarIterations: () => this.grammarIterations,
        show: (n) => this.setIterations(n),
      },
      { maxIterations: Number(els.iterations.max) },
    );
    els.iterations.addEventListener('input', () => {
      this.playback.pause();
      this.tooMany = false;
      this.showOverride();
      this.changed();
    });
    els.iterationsReset.addEventListener('click', () => {
      this.playback.pause();
      this.setIterations(undefined);
      els.iterations.focus();
    });
    this.showOverride();
    els.stepBack.addEventListener('click', () => this.playback.stepBy(-1));
    els.stepForward.addEventListener('click', () => this.playback.stepBy(+1));
    els.seed.addEventListener('input', () => this.changed());
    els.reroll.addEventListener('click', () => this.reroll());
  }

  /** Calls `listener` whenever the user (or playback) changes the iterations or the seed. */
  onChange(listener: () => void): void {
    this.listeners.add(listener);
  }

  /** The iterations asked for; undefined: the grammar's own (also while the box holds what it does not accept: `-2`, `2.5`). */
  iterations(): number | undefined {
    return this.els.iterations.validity.valid ? wholeNumber(this.els.iterations) : undefined;
  }

  /** The diagnostics the text shows: not the limits the box's number passes (the box says those). */
  ofText(diagnostics: DiagnosticList): DiagnosticList {
    const n = this.iterations();
    return n === undefined || n === this.grammarIterations ? diagnostics : diagnostics.where((_, code) => !ITERATION_ERRORS.has(code));
  }

  /** The seed asked for; undefined: the grammar's own. */
  seed(): number | undefined {
    return wholeNumber(this.els.seed);
  }

  /** A new random seed. */
  reroll(): void {
    this.els.seed.value = String(crypto.getRandomValues(new Uint32Array(1))[0]);
    this.changed();
  }

  /**
   * A build was delivered: its grammar's iterations are shown (unless other errors leave them
   * unknown), the errors the box's value caused are told, and playback goes on.
   */
  buildShown(build: Pick<PlantBuild, 'grammarIterations' | 'diagnostics'>): void {
    if (!build.diagnostics.some((severity, code) => severity === 'error' && !ITERATION_ERRORS.has(code))) this.grammarIterations = build.grammarIterations;
    const errors = overrideErrors(this.iterations(), this.grammarIterations, build.diagnostics);
    this.tooMany = errors !== null;
    if (errors) this.notice?.show('error', errors.message, errors.items, OVERRIDE_TOPIC);
    else this.notice?.hide(OVERRIDE_TOPIC);
    this.showOverride();
    this.playback.shownBuild();
  }

  /**
   * The text changed: when its iterations line changed, the user means the grammar's new value,
   * so the box's override is dropped (a build follows through `onChange`).
   */
  textChanged(text: string): void {
    const line = writtenIterations(text);
    const edited = this.iterationsLine !== undefined && line !== this.iterationsLine;
    this.iterationsLine = line;
    if (edited && this.iterations() !== undefined) {
      this.playback.pause();
      this.setIterations(undefined);
    }
  }

  /** Another text is opened: playback stops and the grammar's own iterations and seed apply. */
  clear(): void {
    this.playback.pause();
    this.applyShared({});
  }

  /** The overrides for a share link (absent: the grammar's own). */
  toShared(): SharedDerivation {
    const shared: SharedDerivation = {};
    const iterations = this.iterations();
    const seed = this.seed();
    if (iterations !== undefined) shared.iterations = iterations;
    if (seed !== undefined) shared.seed = seed;
    return shared;
  }

  /** Shows a link's overrides (absent: the grammar's own); the caller asks for the build. */
  applyShared(state: SharedDerivation): void {
    this.els.iterations.value = state.iterations === undefined ? '' : String(state.iterations);
    this.els.seed.value = state.seed === undefined ? '' : String(state.seed);
    this.showOverride();
  }

  /** Puts `n` in the box (undefined: empties it) and asks for a build. */
  private setIterations(n: number | undefined): void {
    this.els.iterations.value = n === undefined ? '' : String(n);
    this.showOverride();
    this.changed();
  }

  /**
   * Shows which iterations are in force: the box's, marked as overriding the grammar's (not when
   * they are the grammar's), or the grammar's as placeholder; and at the box, what it does not
   * accept (the grammar is not to blame for it): not a whole number from 0 to its maximum, or too many.
   */
  private showOverride(): void {
    const { iterations, iterationsBox, iterationsTag, iterationsReset } = this.els;
    const override = this.iterations();
    const grammar = this.grammarIterations;
    const refused = this.tooMany ? 'too many' : iterations.validity.valid ? '' : `whole, 0–${iterations.max}`;
    const marked = refused !== '' || (override !== undefined && override !== grammar);
    iterations.placeholder = `grammar: ${grammar}`;
    iterationsBox.style.setProperty('--digits', String(String(grammar).length)); // (the box's width, iterations-box.css)
    iterationsBox.toggleAttribute('data-override', marked);
    iterations.setAttribute('aria-invalid', String(refused !== ''));
    iterationsTag.textContent = refused || `overrides ${grammar}`;
    iterationsReset.hidden = !marked;
    iterations.title = refused
      ? `Iterations: ${refused}`
      : override === undefined
        ? `The grammar's own iterations (${grammar}) are in force; type a number to override them`
        : `${override} iterations override the grammar's ${grammar}; × or an empty box uses the grammar's`;
  }

  private changed(): void {
    for (const listener of this.listeners) listener();
  }
}
