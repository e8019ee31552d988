// The studio's FrameScene: the view on screen, its growth time set where the view can show growth
// (issue 45's `setGrowthTime`), its camera turned about the plant, each frame drawn by the view at
// the movie's size (../../../view/snapshot.ts `filmFrames`).
import type { FilmFrames, PictureLook, PlantView } from '../../../view';
import type { FrameScene } from './frame-scene';

/** What a view that shows growth in time adds (slice g3's `PlantView` methods; absent, the plant is shown whole). */
interface GrowingView {
  setGrowthTime?: (t: number | null) => void;
  growthSpan?: () => number | null;
}

/**
 * The growth time span the view's plant can be filmed over, `[0, N]`: N when the plant on screen
 * carries growth times, else null (a movie then turns the whole plant).
 */
export function growthSpanOf(view: PlantView): number | null {
  const growing = view as unknown as GrowingView;
  return typeof growing.growthSpan === 'function' ? growing.growthSpan() : null;
}

/** A scene to film and the function that puts the view back when the movie is done or cancelled. */
export interface FilmedScene extends FrameScene {
  close(): void;
}

/** Films `view` in `look`: the view draws nothing else until `close`, which shows the plant whole again. */
export async function viewScene(view: PlantView, look: PictureLook): Promise<FilmedScene> {
  const film: FilmFrames = await view.film(look);
  const growing = view as unknown as GrowingView;
  const grow = typeof growing.setGrowthTime === 'function' && growthSpanOf(view) !== null ? growing.setGrowthTime.bind(view) : undefined;
  return {
    at: (t, turn) => {
      grow?.(t);
      film.turn(turn);
    },
    draw: (width, height) => film.draw(width, height),
    close: () => {
      grow?.(null);
      film.close();
    },
  };
}
