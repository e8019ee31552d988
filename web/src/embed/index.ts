// Embeds: a plant on any page, without the studio. `element.ts` is `<meristem-plant>` (built to
// meristem-plant.js), `embed-page.ts` runs `embed.html` (a plant from a studio link); both show an
// `EmbedPlant` (`embed-plant.ts`: a view, iterations and sliders) and build in one worker per page
// (`shared-builds.ts`, through `../build`). vite.config.ts and embed.html name the two entry files.
export { MeristemPlantElement } from './element';
export { EmbedPlant, parseControls, type EmbedControl, type EmbedSettings } from './embed-plant';
export { sharedBuilds, type SharedBuilds } from './shared-builds';
