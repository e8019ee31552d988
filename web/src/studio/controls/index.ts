// The studio's controls around the editor and the view: the Growth panel, the view's options and
// tools, the view following the plant, the layout modes, the splitter, shortcuts. (The sliders and
// playback, which embeds show too, are in ../../plant-controls.)
export { ViewOptions, tubesFor } from './view-options';
export { sidesChoices } from './view-tools';
export { VocabularyPanels } from './vocabulary-panels';
export { wireKeyboard, wireLayout, wireViewControls, type ViewControls } from './wire-controls';
