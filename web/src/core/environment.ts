// What a build knows of its environment (issue 47), copied out of the studio core's build: the
// grids of values (the light grid), the obstacles' solids, the attraction points left and the names
// of a `?E`'s reply values. The studio core's only (the first plant's has no environment): the build
// worker's studio core (./studio-core.ts) gives it to `plainBuild`.
import type { PlantBuild as StudioPlantBuild } from '../../../crate/pkg/meristem.js';
import { ownedArray } from './init';
import type { EnvironmentData, EnvironmentField, EnvironmentSolid } from './types';

/** The environment's JSON as the core writes it (`EnvironmentView::to_json`). */
interface RawEnvironment {
  fields: Omit<EnvironmentField, 'values'>[];
  solids: EnvironmentSolid[];
  points: number;
  replies: string[];
}

/** The environment of `result`, or undefined when its grammar declares none (or the core has none). */
export function environmentOf(result: object): EnvironmentData | undefined {
  if (!('environment' in result)) return undefined;
  const build = result as StudioPlantBuild;
  const raw = JSON.parse(build.environment()) as RawEnvironment | null;
  if (!raw) return undefined;
  return {
    fields: raw.fields.map((field, i) => ({ ...field, values: ownedArray(build.environmentField(i)) })),
    solids: raw.solids,
    points: raw.points > 0 ? ownedArray(build.environmentPoints()) : new Float32Array(0),
    replies: raw.replies,
  };
}
