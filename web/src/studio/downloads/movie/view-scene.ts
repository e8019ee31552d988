// The studio's FrameScene: the view on screen, posed at each frame's growth time as the timeline
// shows it (a timed or stepwise grammar derived at t, ./derived-growth.ts; any other grown by the
// view's growth time, `PlantView.setGrowthTime`, where the plant carries its growth times), its
// camera turned about the plant, each frame drawn by the view at the movie's size
// (../../../view/snapshot.ts `filmFrames`).
import type { FilmFrames, PictureLook, PlantView } from '../../../view';
import type { DerivedGrowth } from './derived-growth';
import type { FrameScene } from './frame-scene';

/** Who holds the view's frame while a movie of a derived plant is filmed: each plant is not framed anew. */
const FRAME_HOLDER = 'movie';

/**
 * The growth time span the view's plant can be filmed over, `[0, N]`: a derived plant's steps, or
 * N when the plant on screen carries growth times, else null (a movie then turns the whole plant).
 */
export function growthSpanOf(view: PlantView, derived?: DerivedGrowth | null): number | null {
  return derived ? derived.span : view.growthSpan();
}

/** A scene to film and the function that puts the view back when the movie is done or cancelled. */
export interface FilmedScene extends FrameScene {
  close(): void;
}

/**
 * Films `view` in `look`, the plant posed by `derived` when it is derived at t: the view draws
 * nothing else until `close`, which shows the plant whole again (a derived one at the time the
 * studio showed). A derived plant is filmed with the camera on its whole plant (its own
 * iterations), where the timeline's camera on the final plant keeps it.
 */
export async function viewScene(view: PlantView, look: PictureLook, derived?: DerivedGrowth | null): Promise<FilmedScene> {
  if (derived) {
    try {
      await derived.show(derived.span); // (the whole plant, framed as the timeline frames it)
    } catch (error) {
      derived.restore();
      throw error;
    }
    view.holdFrame(FRAME_HOLDER, true);
  }
  const growing = !derived && view.growthSpan() !== null;
  if (growing) await view.growthReady; // the growth's shaders, before the first frame
  // (In the Lines mode or the Tubes mode, as on screen: both grow.)
  let film: FilmFrames;
  try {
    film = await view.film(look);
  } catch (error) {
    if (derived) release(view, derived);
    throw error;
  }
  let open = true;
  return {
    at: async (t, turn) => {
      if (derived) await derived.show(t);
      else if (growing) view.setGrowthTime(t);
      film.turn(turn);
    },
    draw: (width, height) => {
      if (!open) throw new Error('the movie was closed');
      return film.draw(width, height);
    },
    close: () => {
      if (!open) return;
      open = false;
      if (growing) view.setGrowthTime(null);
      film.close();
      if (derived) release(view, derived);
    },
  };
}

/** Lets the view's frame go and puts the studio back at the time it showed before the movie. */
function release(view: PlantView, derived: DerivedGrowth): void {
  view.holdFrame(FRAME_HOLDER, false);
  derived.restore();
}
