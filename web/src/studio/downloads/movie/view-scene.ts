// The studio's FrameScene: the view on screen, its growth time set where the plant carries its
// growth times (`PlantView.setGrowthTime`), its camera turned about the plant, each frame drawn by
// the view at the movie's size (../../../view/snapshot.ts `filmFrames`).
import type { FilmFrames, PictureLook, PlantView } from '../../../view';
import type { FrameScene } from './frame-scene';

/**
 * The growth time span the view's plant can be filmed over, `[0, N]`: N when the plant on screen
 * carries growth times, else null (a movie then turns the whole plant).
 */
export function growthSpanOf(view: PlantView): number | null {
  return view.growthSpan();
}

/** A scene to film and the function that puts the view back when the movie is done or cancelled. */
export interface FilmedScene extends FrameScene {
  close(): void;
}

/** Films `view` in `look`: the view draws nothing else until `close`, which shows the plant whole again. */
export async function viewScene(view: PlantView, look: PictureLook): Promise<FilmedScene> {
  const growing = view.growthSpan() !== null;
  if (growing) await view.growthReady; // the growth's shaders, before the first frame
  // (In the Lines mode or the Tubes mode, as on screen: both grow.)
  const film: FilmFrames = await view.film(look);
  return {
    at: (t, turn) => {
      if (growing) view.setGrowthTime(t);
      film.turn(turn);
    },
    draw: (width, height) => film.draw(width, height),
    close: () => {
      if (growing) view.setGrowthTime(null);
      film.close();
    },
  };
}
