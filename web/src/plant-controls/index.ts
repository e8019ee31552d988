// The controls of one plant, the studio's and an embed's alike: the derivation played step by
// step (`playback.ts`) and the sliders of the grammar's constants (`sliders.ts`).
export { Playback } from './playback';
export { SliderPanel } from './sliders';
