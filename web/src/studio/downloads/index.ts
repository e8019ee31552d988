// Downloads: the plant on screen as a model or a picture, exported in a worker of its own; the
// Downloads menu loads after the first plant (downloads-loader.ts).
export { loadDownloads } from './downloads-loader';
