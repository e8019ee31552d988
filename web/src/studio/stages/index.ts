// Stages: the iterations side by side, grown in a worker of their own; loaded when first turned on
// (stages-loader.ts), so only the loader is re-exported.
export { LazyStagesMode } from './stages-loader';
