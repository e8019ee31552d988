// The view follows the plant (PlantView refits every new plant until the user moves the camera);
// this piece adds what the studio knows around it: the "Refit" hint, the frame held while branches
// are edited, and how Play frames the growth: in the last step's frame from the start (the default,
// so the plant is seen growing in one picture, as in ABOP's developmental sequences), or fitting
// every step as it appears.
import type { Bounds } from '../../core';
import type { PlantView } from '../../view';
import type { Playback } from '../../plant-controls';
import type { BuildResult } from '../../build';

/** How Play frames the plant: `last`: in the last step's frame from the start; `each`: every step fitted. */
export type PlayFraming = 'last' | 'each';

/** The controls (see index.html). */
export interface ViewFollowingElements {
  /** The hint shown when a new plant was not framed because the camera had been moved. */
  refit: HTMLButtonElement;
  /** The radio buttons of the Play framing, valued `last` and `each`. */
  playFraming: RadioNodeList | HTMLInputElement[];
}

/** What a build is of, apart from its iterations: two builds with the same key grow the same plant. */
export function growthKey(result: Pick<BuildResult, 'source' | 'options'>): string {
  const { iterations: _, ...options } = result.options;
  return JSON.stringify(options) + '\n' + result.source;
}

/** Whether `result` is the grammar's own last step (its `#iterations`, not fewer). */
export function isLastStep(result: Pick<BuildResult, 'options' | 'build'>): boolean {
  return (result.options.iterations ?? result.build.grammarIterations) === result.build.grammarIterations;
}

/** Connects the view's following to the Refit hint, Play and branch editing. */
export class ViewFollowing {
  private framing: PlayFraming = 'last';
  /** The bounds of the last step's plant of the last grammar shown at its own iterations. */
  private lastStep: { key: string; bounds: Bounds } | undefined;

  constructor(
    els: ViewFollowingElements,
    private readonly view: PlantView,
    /** The plant on screen (the last good build). */
    private readonly shown: () => BuildResult | undefined,
  ) {
    els.refit.addEventListener('click', () => view.frame());
    view.onRefitHint((hinted) => (els.refit.hidden = !hinted));
    for (const radio of els.playFraming) {
      const input = radio as HTMLInputElement;
      input.addEventListener('change', () => input.checked && (this.framing = input.value === 'each' ? 'each' : 'last'));
    }
  }

  /** How Play frames the plant now. */
  get playFraming(): PlayFraming {
    return this.framing;
  }

  /** A build is on screen: the last step's bounds are kept for Play. */
  delivered(result: BuildResult): void {
    if (result.build.ok && isLastStep(result)) this.lastStep = { key: growthKey(result), bounds: result.build.stats.bounds };
  }

  /** Connects Play: while it plays, the view shows the growth as {@link playFraming} says. */
  follow(playback: Playback): void {
    playback.onPlayingChange((playing) => (playing ? this.playStarted() : this.view.holdFrame('play', false)));
  }

  /** Branch editing holds the frame: a reshaped plant never makes the camera jump. */
  editing(on: boolean): void {
    this.view.holdFrame('editing', on);
  }

  private playStarted(): void {
    const shown = this.shown();
    const last = this.lastStep;
    if (this.framing === 'last' && shown && last && last.key === growthKey(shown)) {
      this.view.frame(last.bounds);
      this.view.holdFrame('play', true);
    } else {
      // Every step fitted (also when the last step's plant has not been seen with these options).
      this.view.followAgain();
    }
  }
}
