// A vite plugin that serves the course (public/lessons/*.md, read by scripts/lesson-files.ts) in
// dev and emits it at build: `lessons/index.json` (the list) and `lessons/SLUG.json` (each lesson:
// its HTML, grammars and tasks), from the same function, so `npm start` and `npm run build` agree.
// A malformed lesson fails the build with its file and line; in dev the request answers 500 with
// the same message, which the Learn panel shows. Nothing is written into public/.
import type { Plugin } from 'vite';
import { lessonIndex, readLessons } from './lesson-files.ts';

/** Where the list of lessons is, relative to the page. */
export const LESSON_INDEX_PATH = 'lessons/index.json';

/** The files the plugin serves and emits: path relative to the page → JSON text. */
export function lessonAssets(dir: string): Map<string, string> {
  const lessons = readLessons(dir);
  const json = (value: unknown) => `${JSON.stringify(value, null, 1)}\n`;
  const assets = new Map([[LESSON_INDEX_PATH, json(lessonIndex(lessons))]]);
  for (const lesson of lessons) assets.set(`lessons/${lesson.slug}.json`, json(lesson));
  return assets;
}

/** The plugin; `lessonsDir` is the folder of the `.md` files (public/lessons). */
export function lessonsPlugin(lessonsDir: string): Plugin {
  return {
    name: 'meristem-lessons',
    configureServer(server) {
      // Read on every request, so a lesson edited while `npm start` runs shows at once.
      server.middlewares.use((request, response, next) => {
        const path = (request.url ?? '').split('?')[0];
        const match = /\/(lessons\/[a-z0-9-]+\.json)$/.exec(path);
        if (!match) return next();
        let assets: Map<string, string>;
        try {
          assets = lessonAssets(lessonsDir);
        } catch (error) {
          response.statusCode = 500;
          response.setHeader('Content-Type', 'text/plain; charset=utf-8');
          response.end(String(error instanceof Error ? error.message : error));
          return;
        }
        const body = assets.get(match[1]);
        if (body === undefined) return next();
        response.setHeader('Content-Type', 'application/json');
        response.end(body);
      });
    },
    generateBundle() {
      let assets: Map<string, string>;
      try {
        assets = lessonAssets(lessonsDir);
      } catch (error) {
        this.error(error instanceof Error ? error.message : String(error));
      }
      for (const [fileName, source] of assets) this.emitFile({ type: 'asset', fileName, source });
    },
  };
}
