// Variants: two to six plants side by side, cameras linked, with their figures and diffs; loaded
// when first opened (variants-loader.ts), so only the loader is re-exported.
export { lazyVariants, type LazyVariants } from './variants-loader';
