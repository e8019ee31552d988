// The view follows the plant (PlantView refits every new plant until the user moves the camera);
// this piece adds what the studio knows around it: the "Refit" hint, and the frame held while
// branches are edited. (While the growth plays, the timeline's camera frames it: ../timeline.)
import type { PlantView } from '../../view';
import type { BuildResult } from '../../build';

/** The controls (see index.html). */
export interface ViewFollowingElements {
  /** The hint shown when a new plant was not framed because the camera had been moved. */
  refit: HTMLButtonElement;
}

/** What a build is of, apart from its iterations: two builds with the same key grow the same plant (Stages reads it). */
export function growthKey(result: Pick<BuildResult, 'source' | 'options'>): string {
  const { iterations: _, ...options } = result.options;
  return JSON.stringify(options) + '\n' + result.source;
}

/** Connects the view's following to the Refit hint and branch editing. */
export class ViewFollowing {
  constructor(
    els: ViewFollowingElements,
    private readonly view: PlantView,
  ) {
    els.refit.addEventListener('click', () => view.frame());
    view.onRefitHint((hinted) => (els.refit.hidden = !hinted));
  }

  /** Branch editing holds the frame: a reshaped plant never makes the camera jump. */
  editing(on: boolean): void {
    this.view.holdFrame('editing', on);
  }
}
