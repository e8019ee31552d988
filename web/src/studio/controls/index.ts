// The controls around the editor and the view: sliders, the Growth panel, playback, the view's
// options and tools, the view following the plant, the layout modes, the splitter, shortcuts.
export { SliderPanel } from './sliders';
export { Playback } from './playback';
export { ViewOptions, tubesFor } from './view-options';
export { sidesChoices } from './view-tools';
export { growthKey } from './view-following';
export { VocabularyPanels } from './vocabulary-panels';
export { wireKeyboard, wireLayout, wireViewControls, type ViewControls } from './wire-controls';
