// The controls of one plant, the studio's and an embed's alike: the derivation stepped whole
// iterations at a time (`playback.ts`), the growth played in continuous time (`timeline.ts`, a door
// of its own: it loads with the timeline, after the first plant) and the sliders of the grammar's
// constants (`sliders.ts`, loaded on first use through `lazy-sliders.ts`).
export { Playback } from './playback';
export { LazySliderPanel } from './lazy-sliders';
export { derivedBuildOptions, derivedTime } from './derived-at';
