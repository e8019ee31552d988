// Recording a movie: each frame posed and drawn by the scene, handed to the format's writer, the
// page given back its thread between frames (the progress paints, Cancel is heard). Cancel stops
// at once and lets go of everything written.
import type { FrameScene } from './frame-scene';
import { frameTime, frameTurn, type MoviePlan } from './movie-plan';
import type { MovieWriter } from './movie-writer';

/** A movie being recorded: `done` settles with the file, or null when cancelled. */
export interface RecordingMovie {
  done: Promise<Blob | null>;
  cancel(): void;
}

/** Gives the page its thread back for a moment (a task, not a frame: paints and clicks come in between). */
function yieldToPage(): Promise<void> {
  return new Promise((resolve) => {
    const channel = new MessageChannel();
    channel.port1.onmessage = () => resolve();
    channel.port2.postMessage(null);
  });
}

/** The writer of `plan`'s format; a GIF's palette comes from the range's last frame (the whole plant), drawn first. */
async function writerFor(plan: MoviePlan, scene: FrameScene, name: string): Promise<MovieWriter> {
  const { format, width, height, fps } = plan;
  if (format === 'webm' || format === 'mp4') return (await import('./video-writer')).videoWriter(format, width, height, fps);
  if (format === 'png') return (await import('./png-sequence')).pngSequenceWriter(name, plan.frames);
  const { gifWriter } = await import('./gif-writer');
  await scene.at(plan.to, 0);
  return gifWriter(width, height, fps, scene.draw(width, height));
}

/**
 * Records `plan` from `scene`: frame i at growth time {@link frameTime} and turn {@link frameTurn},
 * `onFrame(done, frames)` told after each. `name` names a PNG sequence's files; `makeWriter` is
 * the format's writer (a fake one in unit tests).
 */
export function recordMovie(
  plan: MoviePlan,
  scene: FrameScene,
  name: string,
  onFrame: (done: number, frames: number) => void,
  makeWriter: typeof writerFor = writerFor,
): RecordingMovie {
  let cancelled = false;
  let writer: MovieWriter | undefined;
  let stop = () => {};
  // Cancel settles the movie at once, even while a frame waits for its scene (a plant derived
  // at t may take a while to build): the frame under way is dropped when it comes.
  const stopped = new Promise<null>((resolve) => (stop = () => resolve(null)));
  const record = async (): Promise<Blob | null> => {
    writer = await makeWriter(plan, scene, name);
    for (let index = 0; index < plan.frames; index++) {
      if (cancelled) return null;
      await scene.at(frameTime(index, plan.frames, plan.from, plan.to), frameTurn(index, plan.frames, plan.turntable));
      if (cancelled) return null;
      await writer.add(scene.draw(plan.width, plan.height), index);
      onFrame(index + 1, plan.frames);
      await yieldToPage();
    }
    return cancelled ? null : writer.finish();
  };
  const recorded = record().then(
    (file) => (cancelled ? null : file),
    (error: unknown) => {
      writer?.close();
      if (cancelled) return null; // (a writer closed under a frame being added)
      throw error;
    },
  );
  return {
    done: Promise.race([recorded, stopped]),
    cancel: () => {
      cancelled = true;
      writer?.close();
      stop();
    },
  };
}
