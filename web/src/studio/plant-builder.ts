// Builds with a one-entry cache, so the 3D view and the editor's linter share one build per edit.
import { buildPlant, type PlantBuild } from '../core';

/** A build and how long it took. */
export interface TimedBuild {
  build: PlantBuild;
  /** Wall-clock time of the core call, in milliseconds. */
  millis: number;
}

/**
 * Remembers the last build: asking again for the same source and iterations returns it without
 * running the core a second time.
 */
export class PlantBuilder {
  private last: { source: string; iterations: number | undefined; result: TimedBuild } | undefined;

  /** The build of `source` with `iterations` (undefined: the grammar's own). May throw if the core crashes. */
  build(source: string, iterations: number | undefined): TimedBuild {
    if (this.last && this.last.source === source && this.last.iterations === iterations) return this.last.result;
    const start = performance.now();
    const build = buildPlant(source, { iterations });
    const result = { build, millis: performance.now() - start };
    this.last = { source, iterations, result };
    return result;
  }
}
