// Thumbnails of the gallery, drawn in the browser on first view with the studio's own renderer,
// in a worker of their own (thumbnail-worker.ts), one example at a time; kept in memory as object
// URLs for the rest of the visit. The worker and its WebGL context go when the queue is empty.
import type { ThumbnailRequest, ThumbnailResponse } from './thumbnail-worker';

/** Fetches an example's text. */
export type ExampleText = (file: string) => Promise<string>;

function createThumbnailWorker(): Worker {
  return new Worker(new URL('./thumbnail-worker.ts', import.meta.url), { type: 'module', name: 'meristem-thumbnails' });
}

/** A picture URL per example file, or `null` when it could not be drawn. */
export class GalleryThumbnails {
  private readonly pictures = new Map<string, string | null>();
  private queue: string[] = [];
  private readonly listeners = new Set<(file: string, url: string | null) => void>();
  private running = false;

  constructor(private readonly exampleText: ExampleText) {}

  /** The picture of `file` if drawn already (`null`: it could not be drawn). */
  picture(file: string): string | null | undefined {
    return this.pictures.get(file);
  }

  /** Calls `listener` as each picture is ready. */
  onPicture(listener: (file: string, url: string | null) => void): void {
    this.listeners.add(listener);
  }

  /** Draws the pictures of `files` not drawn yet, in this order, in the background. */
  request(files: readonly string[]): void {
    this.queue = files.filter((f) => !this.pictures.has(f));
    if (!this.running) void this.drain();
  }

  private async drain(): Promise<void> {
    this.running = true;
    const worker = createThumbnailWorker();
    const answers = new Map<string, (response: ThumbnailResponse) => void>();
    worker.addEventListener('message', (event: MessageEvent<ThumbnailResponse>) => answers.get(event.data.file)?.(event.data));
    const failed = new Promise<ThumbnailResponse>((resolve) =>
      worker.addEventListener('error', (event) => {
        event.preventDefault();
        resolve({ file: '', error: event.message || 'the thumbnail worker could not start' });
      }),
    );
    try {
      for (let file = this.queue.shift(); file !== undefined; file = this.queue.shift()) {
        if (this.pictures.has(file)) continue;
        const request: ThumbnailRequest = { file, source: await this.exampleText(file) };
        const answer = new Promise<ThumbnailResponse>((resolve) => answers.set(request.file, resolve));
        worker.postMessage(request);
        const response = await Promise.race([answer, failed]);
        answers.delete(file);
        const url = 'picture' in response ? URL.createObjectURL(response.picture) : null;
        if (!url) console.warn(`No gallery thumbnail for ${file}: ${'error' in response ? response.error : ''}`);
        this.pictures.set(file, url);
        for (const listener of this.listeners) listener(file, url);
        if (!('picture' in response) && response.file === '') break; // the worker itself failed
      }
    } catch (error) {
      console.warn('Gallery thumbnails:', error);
    } finally {
      worker.terminate();
      this.running = false;
    }
  }
}
