// typescript-eslint, resolved from this folder, so that it finds the TypeScript 5 installed beside
// it (see package.json) and not the project's TypeScript 7. eslint.config.js imports it from here.
export { default } from 'typescript-eslint';
