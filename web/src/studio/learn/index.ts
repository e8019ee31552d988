// The Learn panel: lessons (issue 17) with their checks; loaded on the first click of its button.
export { installLearnPanel } from './learn-loader';
