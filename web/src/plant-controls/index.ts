// The controls of one plant, the studio's and an embed's alike: the derivation stepped whole
// iterations at a time (`playback.ts`), the growth played in continuous time (`timeline.ts`) and
// the sliders of the grammar's constants (`sliders.ts`).
export { Playback } from './playback';
export { SliderPanel } from './sliders';
export { clampedNumber, SPEED_MAX, SPEED_MIN, TIME_MAX, TIMELINE_SPEEDS, Timeline, type TimelineHost, type TimelineState } from './timeline';
