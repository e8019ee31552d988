// The derivation's controls in the toolbar: the iterations (the box, step −/+, play / pause) and the
// seed (the box, reroll). Empty boxes mean the grammar's own `#iterations` and `#seed`.
import type { SharedState } from '../share/codec';
import { Playback } from './playback';

/** The controls (see index.html). */
export interface DerivationElements {
  iterations: HTMLInputElement;
  stepBack: HTMLButtonElement;
  stepForward: HTMLButtonElement;
  play: HTMLButtonElement;
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

/** The iterations and seed the user asked for, and playback over the iterations. */
export class DerivationControls {
  /** Step −/+ and play over the iterations. */
  readonly playback: Playback;
  /** The grammar's `#iterations` of the last build shown. */
  private grammarIterations = 0;
  private readonly listeners = new Set<() => void>();

  constructor(private readonly els: DerivationElements) {
    this.playback = new Playback(
      {
        shown: () => this.iterations() ?? this.grammarIterations,
        grammarIterations: () => this.grammarIterations,
        show: (n) => {
          els.iterations.value = n === undefined ? '' : String(n);
          this.changed();
        },
      },
      { maxIterations: Number(els.iterations.max) },
    );
    this.playback.onPlayingChange((playing) => {
      els.play.setAttribute('aria-pressed', String(playing));
      els.play.textContent = playing ? 'Pause' : 'Play';
    });
    els.iterations.addEventListener('input', () => {
      this.playback.pause();
      this.changed();
    });
    els.stepBack.addEventListener('click', () => this.playback.stepBy(-1));
    els.stepForward.addEventListener('click', () => this.playback.stepBy(+1));
    els.play.addEventListener('click', () => this.playback.toggle());
    els.seed.addEventListener('input', () => this.changed());
    els.reroll.addEventListener('click', () => this.reroll());
  }

  /** Calls `listener` whenever the user (or playback) changes the iterations or the seed. */
  onChange(listener: () => void): void {
    this.listeners.add(listener);
  }

  /** The iterations asked for; undefined: the grammar's own. */
  iterations(): number | undefined {
    return wholeNumber(this.els.iterations);
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

  /** A build is on screen: its grammar's iterations are the placeholder, and playback goes on. */
  buildShown(grammarIterations: number): void {
    this.grammarIterations = grammarIterations;
    this.els.iterations.placeholder = String(grammarIterations);
    this.playback.shownBuild();
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
  }

  private changed(): void {
    for (const listener of this.listeners) listener();
  }
}
