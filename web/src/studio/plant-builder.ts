// Builds with a one-entry cache, so the 3D view and the editor's linter share one build per edit.
import { inspectPlant, type BuildOptions, type PlantBuild, type PlantInspector } from '../core';

/** A build and how long it took. */
export interface TimedBuild {
  build: PlantBuild;
  /** The core's derivation kept alive for explanations. Whoever shows the build takes it over
   * (`adopted`); otherwise the builder frees it when the next build replaces this one. */
  inspector: PlantInspector;
  adopted: boolean;
  /** Wall-clock time of the core call, in milliseconds. */
  millis: number;
}

/**
 * Remembers the last build: asking again for the same source and options returns it without
 * running the core a second time.
 */
export class PlantBuilder {
  private last: { source: string; key: string; result: TimedBuild } | undefined;

  /** The build of `source` with `options` (iterations, seed, view options). May throw if the core crashes. */
  build(source: string, options: BuildOptions = {}): TimedBuild {
    const key = JSON.stringify([options.iterations, options.seed, options.sides, options.smoothAll]);
    if (this.last && this.last.source === source && this.last.key === key) return this.last.result;
    const start = performance.now();
    const { build, inspector } = inspectPlant(source, options);
    const result: TimedBuild = { build, inspector, adopted: false, millis: performance.now() - start };
    if (this.last && !this.last.result.adopted) this.last.result.inspector.free();
    this.last = { source, key, result };
    return result;
  }
}
