// The growth function of growth in time (issue 45) as the shaders and the CPU share it: the time
// uniform's name, and the smoothstep of the fraction of [t0, t1] passed (the interfaces' g). Part
// of the growth's chunk (./growth.ts, ./line-growth.ts), which loads with the first growth time shown.

/** The name of the time uniform in the shaders. */
export const UNIFORM = 'meristemGrowthTime';

/** The growth function g (smoothstep) of the fraction of [t0, t1] passed at `t`: 0 before t0, 1 after t1. */
export function grownFraction(t: number, t0: number, t1: number): number {
  if (!(t1 > t0)) return 1;
  const x = Math.min(1, Math.max(0, (t - t0) / (t1 - t0)));
  return x * x * (3 - 2 * x);
}
