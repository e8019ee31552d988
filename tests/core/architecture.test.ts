// The studio's side of crate/tests/architecture.rs: it reads every non-test file of web/src.
// - One boundary: only web/src/core/ imports the generated package (crate/pkg).
// - Areas point one way: each folder of web/src is an area that may import only the areas AREAS
//   lets it (core ← editor, view, share, build ← plant-controls ← studio, embed ← main.ts,
//   boot.ts; python, which uses none, ← studio),
//   another area only through its doors (its index.ts, and the few files AREAS names
//   with a reason; a lazy `import()` may name the module it loads: that is where a chunk of the
//   page starts), and no file imports itself back through a cycle of static imports.
// - One vocabulary: the studio names no part of the language the core's vocabulary does not have,
//   and spells none of them for its logic. In the files' literals (strings, templates, regular
//   expressions; comments are skipped):
// - every directive (`#name`, three letters or more, not a colour) and every `@Name`, `?X`, `~x`
//   module a literal mentions is in the vocabulary;
// - no string literal is exactly a name (a directive, a module of two characters or more, a keyword
//   as written), and no regular expression contains one: code reads names from the vocabulary.
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, relative } from 'node:path';
import { describe, expect, it } from 'vitest';
import { languageVocabulary, writtenDirective, writtenKeyword } from '../../web/src/core';

const root = new URL('../../web/src/', import.meta.url).pathname;

function files(dir: string): string[] {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) return files(path);
    return name.endsWith('.ts') && !name.endsWith('.test.ts') && !name.endsWith('.d.ts') ? [path] : [];
  });
}

/** A literal of a TypeScript file: its kind, text and line. */
interface Literal {
  kind: 'string' | 'template' | 'regex';
  text: string;
  line: number;
}

/** The literals of TypeScript source, comments skipped. A `/` starts a regular expression where an operand is expected. */
export function literals(source: string): Literal[] {
  const out: Literal[] = [];
  let line = 1;
  let i = 0;
  let last = ''; // the last significant character, to tell a regex from a division
  while (i < source.length) {
    const c = source[i];
    const next = source[i + 1];
    if (c === '\n') line++;
    if (c === '/' && next === '/') {
      while (i < source.length && source[i] !== '\n') i++;
      continue;
    }
    if (c === '/' && next === '*') {
      const end = source.indexOf('*/', i + 2);
      const stop = end < 0 ? source.length : end + 2;
      line += source.slice(i, stop).split('\n').length - 1;
      i = stop;
      continue;
    }
    if (c === '"' || c === "'" || c === '`' || (c === '/' && /[(,=:[!&|?{};+\-*%<>~^]|^$|return/.test(last))) {
      const kind = c === '`' ? 'template' : c === '/' ? 'regex' : 'string';
      const start = line;
      let text = '';
      let j = i + 1;
      let inClass = false;
      while (j < source.length) {
        const d = source[j];
        if (d === '\\') {
          text += d + source[j + 1];
          j += 2;
          continue;
        }
        if (d === '\n') line++;
        if (kind === 'regex' && d === '[') inClass = true;
        if (kind === 'regex' && d === ']') inClass = false;
        if (d === c && !inClass) break;
        text += d;
        j++;
      }
      out.push({ kind, text, line: start });
      i = j + 1;
      if (kind === 'regex') while (/[a-z]/.test(source[i] ?? '')) i++;
      last = 'x';
      continue;
    }
    if (!/\s/.test(c)) last = /[A-Za-z0-9_$)\]]/.test(c) ? 'x' : c;
    if (source.startsWith('return', i) && !/[A-Za-z0-9_$]/.test(source[i + 6] ?? '')) last = 'return';
    i++;
  }
  return out;
}

/** The directives and modules a literal mentions. */
function mentioned(text: string): string[] {
  const names: string[] = [];
  for (const m of text.matchAll(/(?<![\w#])(#[a-z][a-z_]{2,}|@[A-Z][A-Za-z]*|\?[A-Z](?![A-Za-z])|~[a-z](?![A-Za-z]))/g)) {
    if (!/^#[0-9a-f]{3,8}$/.test(m[1])) names.push(m[1]);
  }
  return names;
}

const vocabulary = languageVocabulary();
const known = new Set([...vocabulary.modules.map((m) => m.name), ...vocabulary.directives.map(writtenDirective)]);
const spelled = [
  ...vocabulary.directives.map(writtenDirective),
  ...vocabulary.modules.map((m) => m.name).filter((n) => n.length > 1),
  ...vocabulary.keywords.flatMap((k) => [writtenKeyword(k), ...(k.aliases ?? []).map((a) => (k.colon ? `${a}:` : a))]),
];

describe('the boundary', () => {
  it('is crossed only in web/src/core', () => {
    const crossing = files(root)
      .filter((file) => /from ['"][./]*\/crate\/pkg(-core)?\//.test(readFileSync(file, 'utf8')))
      .map((file) => relative(root, file))
      .filter((file) => !file.startsWith('core/'));
    expect(crossing).toEqual([]);
    expect(files(root).some((file) => relative(root, file) === 'core/init.ts')).toBe(true);
  });
});

describe('the studio and the vocabulary', () => {
  it('mentions only names the vocabulary has, and spells none for its logic', () => {
    const problems: string[] = [];
    for (const file of files(root)) {
      const where = relative(root, file);
      for (const literal of literals(readFileSync(file, 'utf8'))) {
        for (const name of mentioned(literal.text)) {
          if (!known.has(name)) problems.push(`${where}:${literal.line}: ${literal.kind} names ${name}, which the vocabulary does not have`);
        }
        if (literal.kind === 'string' && spelled.includes(literal.text)) {
          problems.push(`${where}:${literal.line}: '${literal.text}' spells a name of the language: read it from languageVocabulary()`);
        }
        if (literal.kind === 'regex') {
          for (const name of spelled) {
            if (literal.text.includes(name.replace(':', ''))) problems.push(`${where}:${literal.line}: /${literal.text}/ spells "${name}": build it from languageVocabulary()`);
          }
        }
      }
    }
    expect(problems).toEqual([]);
  });

  it('catches a name spelled in a string or a regex, and an unknown one', () => {
    const found = literals("const a = '#define'; const r = /^#angle\\s+/; // '#gone'\nconst t = `use @Foo`; const x = 4 / 2 / 1;");
    expect(found.map((l) => [l.kind, l.text])).toEqual([
      ['string', '#define'],
      ['regex', '^#angle\\s+'],
      ['template', 'use @Foo'],
    ]);
    expect(spelled).toContain('#define');
    expect(mentioned('use @Foo and #angle, not #fff')).toEqual(['@Foo', '#angle']);
    expect(known.has('@Foo')).toBe(false);
  });
});

/**
 * The areas of web/src: the areas each may import (its own is always allowed), and its doors, the
 * files other areas may import statically (`index.ts` unless said otherwise; `*` stands for one
 * folder). Each door beside an index says why it is one.
 */
interface Area {
  uses: string[];
  doors?: string[];
}

const AREAS: Record<string, Area> = {
  // compile.ts: the boot script and the build worker's start compile the core without the facade
  // (and without the wasm-bindgen glue); branches.ts: the edits document's shape, which share
  // links check (edits-check.ts, loaded with the first link that has edits).
  core: { uses: [], doors: ['core/index.ts', 'core/compile.ts', 'core/branches.ts', 'core/edits-check.ts'] },
  // index.ts brings CodeMirror, which loads after the first plant: the plain textarea before it
  // and what the first plant's panels read of the text (defines, a directive's line, growth
  // directives, the reference's anchors) are doors of their own.
  // surface-lines.ts: the Surfaces menu reads which surfaces the text declares from the first plant on;
  // curve-lines.ts: the curve editor (loaded on first use) reads and rewrites a curve's numbers.
  editor: { uses: ['core'], doors: ['editor/index.ts', 'editor/grammar-text.ts', 'editor/defines.ts', 'editor/growth-directives.ts', 'editor/directive-lines.ts', 'editor/reference.ts', 'editor/surface-lines.ts', 'editor/curve-lines.ts'] },
  // highlight.ts: the highlight colours, for panels loaded on demand without the view's three.js
  // code; thumbnail.ts: the gallery's thumbnail worker draws without a page.
  // stages-view.ts and stages-layout.ts: the Stages panel's own scene, loaded with that panel on demand.
  view: { uses: ['core'], doors: ['view/index.ts', 'view/highlight.ts', 'view/thumbnail.ts', 'view/stages-view.ts', 'view/stages-layout.ts'] },
  // variants-state.ts: the Variants view's plants in a link, their shape and limits, for the view (loaded on demand).
  share: { uses: ['core'], doors: ['share/index.ts', 'share/variants-state.ts'] },
  // build-worker-start.ts: the boot script starts the build worker before the studio's script.
  build: { uses: ['core'], doors: ['build/index.ts', 'build/build-worker-start.ts'] },
  // Pyodide's worker and its client: no part of the core (the core reads what Python derived).
  python: { uses: [] },
  // timeline.ts: the growth timeline, loaded with the studio's timeline bar and by animated embeds,
  // never by the first plant.
  'plant-controls': { uses: ['core', 'editor'], doors: ['plant-controls/index.ts', 'plant-controls/timeline.ts'] },
  studio: { uses: ['core', 'editor', 'view', 'share', 'build', 'plant-controls', 'python'], doors: ['studio/*/index.ts', 'studio/parts.ts', 'studio/test-hook.ts'] },
  embed: { uses: ['core', 'view', 'share', 'build', 'plant-controls'] },
  main: { uses: ['core', 'editor', 'view', 'share', 'build', 'plant-controls', 'python', 'studio', 'embed'] },
};

/** Whether `file` is one of an area's doors (`*` matches one folder name). */
function isDoor(file: string, area: string, table: Record<string, Area>): boolean {
  const doors = table[area]?.doors ?? [`${area}/index.ts`];
  return doors.some((door) => new RegExp(`^${door.replace(/[.]/g, '\\.').replace(/\*/g, '[^/]+')}$`).test(file));
}

/** The area of a file of web/src: its folder, or `main` for the files at the top (main.ts, boot.ts). */
function areaOf(file: string): string {
  return file.includes('/') ? file.slice(0, file.indexOf('/')) : 'main';
}

/** One import of a file: what it names, and how (a lazy `import()` or a worker's URL starts another chunk). */
interface Import {
  specifier: string;
  line: number;
  kind: 'static' | 'type' | 'lazy' | 'worker';
}

/** The imports of TypeScript source: `import … from`, `export … from`, bare `import '…'`, `import('…')` and `new Worker(new URL('…', import.meta.url))`. */
export function imports(source: string): Import[] {
  const patterns: [RegExp, (m: RegExpMatchArray) => Import['kind']][] = [
    [/^[ \t]*(?:import|export)\s+(type\s+)?[^;'"]*?\bfrom\s*['"]([^'"]+)['"]/gm, (m) => (m[1] ? 'type' : 'static')],
    [/^[ \t]*import\s*()['"]([^'"]+)['"]/gm, () => 'static'],
    [/\bimport\(\s*()['"]([^'"]+)['"]\s*\)/g, () => 'lazy'],
    [/\bnew\s+(?:Shared)?Worker\(\s*new\s+URL\(\s*()['"]([^'"]+)['"]\s*,\s*import\.meta\.url/g, () => 'worker'],
  ];
  return patterns
    .flatMap(([pattern, kind]) =>
      [...source.matchAll(pattern)].map((m) => ({
        specifier: m[2],
        line: source.slice(0, m.index).split('\n').length,
        kind: kind(m),
      })),
    )
    .sort((a, b) => a.line - b.line);
}

/** The file of web/src a relative specifier names (relative to web/src), or undefined for a package or a file elsewhere. */
function resolve(from: string, specifier: string, known: Set<string>): string | undefined {
  if (!specifier.startsWith('.')) return undefined;
  const path = relative(root, join(root, dirname(from), specifier.replace(/\?.*$/, '')));
  return [path, `${path}.ts`, `${path}/index.ts`].find((candidate) => known.has(candidate));
}

/** An arrow between two files of web/src. */
interface Arrow {
  from: string;
  to: string;
  line: number;
  kind: Import['kind'];
}

/** Every import of every non-test file of web/src that names another file of web/src. */
function arrows(sources: Map<string, string>): Arrow[] {
  const known = new Set(sources.keys());
  return [...sources].flatMap(([from, source]) =>
    imports(source).flatMap(({ specifier, line, kind }) => {
      const to = resolve(from, specifier, known);
      return to === undefined ? [] : [{ from, to, line, kind }];
    }),
  );
}

/** The arrows that break the table: a forbidden area, or another area's module other than its index.ts. */
function wrongArrows(all: Arrow[], table: Record<string, Area>): string[] {
  return all.flatMap(({ from, to, line, kind }) => {
    const [source, target] = [areaOf(from), areaOf(to)];
    if (source === target) return [];
    if (!(source in table)) return [`${from}: area ${source} is not in AREAS`];
    if (!table[source].uses.includes(target)) return [`${from}:${line}: ${source} imports ${target} (${to})`];
    const direct = kind === 'static' || kind === 'type';
    if (direct && !isDoor(to, target, table)) return [`${from}:${line}: imports ${to}, not a door of ${target}`];
    return [];
  });
}

/**
 * The import cycles among the static imports, each as its files in order, the first repeated at
 * the end. Type imports are left out: they are erased before anything runs, so they order no
 * module's evaluation, and the studio's areas name each other's types through `studio/parts.ts`
 * (the parts every `wire…` call takes) by design.
 */
function cycles(all: Arrow[]): string[][] {
  const next = new Map<string, string[]>();
  for (const { from, to, kind } of all) {
    if (kind === 'static') next.set(from, [...(next.get(from) ?? []), to]);
  }
  // Tarjan's strongly connected components; every component of two files or more (or a file
  // importing itself) holds a cycle, reported as one path through it.
  const index = new Map<string, number>();
  const low = new Map<string, number>();
  const stack: string[] = [];
  const found: string[][] = [];
  const visit = (file: string): void => {
    index.set(file, index.size);
    low.set(file, index.get(file)!);
    stack.push(file);
    for (const to of next.get(file) ?? []) {
      if (!index.has(to)) {
        visit(to);
        low.set(file, Math.min(low.get(file)!, low.get(to)!));
      } else if (stack.includes(to)) {
        low.set(file, Math.min(low.get(file)!, index.get(to)!));
      }
    }
    if (low.get(file) !== index.get(file)) return;
    const component = stack.splice(stack.indexOf(file));
    if (component.length > 1 || (next.get(file) ?? []).includes(file)) found.push(cycleThrough(component, next));
  };
  for (const file of [...next.keys()].sort()) if (!index.has(file)) visit(file);
  return found;
}

/** One cycle inside a strongly connected component: from its first file, breadth-first back to it. */
function cycleThrough(component: string[], next: Map<string, string[]>): string[] {
  const inside = new Set(component);
  const start = [...component].sort()[0];
  const paths = new Map<string, string[]>([[start, [start]]]);
  const queue = [start];
  while (queue.length > 0) {
    const file = queue.shift()!;
    for (const to of (next.get(file) ?? []).filter((f) => inside.has(f))) {
      if (to === start) return [...paths.get(file)!, start];
      if (!paths.has(to)) {
        paths.set(to, [...paths.get(file)!, to]);
        queue.push(to);
      }
    }
  }
  return [start, start];
}

describe('the import graph of web/src', () => {
  const sources = new Map(files(root).map((file) => [relative(root, file), readFileSync(file, 'utf8')]));
  const all = arrows(sources);

  it('points one way, between areas through their doors', () => {
    expect(wrongArrows(all, AREAS)).toEqual([]);
  });

  it('has no cycle', () => {
    expect(cycles(all).map((cycle) => cycle.join(' → '))).toEqual([]);
  });

  it('finds a wrong arrow and a cycle', () => {
    const found = imports("import type { A } from './a';\n// import { no } from './comment';\nexport { b } from '../view/b';\nconst c = await import('./c');\nnew Worker(new URL('./w.ts', import.meta.url));\nimport './side';");
    expect(found.map((i) => [i.kind, i.specifier, i.line])).toEqual([
      ['type', './a', 1],
      ['static', '../view/b', 3],
      ['lazy', './c', 4],
      ['worker', './w.ts', 5],
      ['static', './side', 6],
    ]);
    const example: Arrow[] = [
      { from: 'core/a.ts', to: 'view/index.ts', line: 1, kind: 'static' },
      { from: 'studio/a.ts', to: 'view/camera.ts', line: 2, kind: 'static' },
      { from: 'studio/a.ts', to: 'view/lazy.ts', line: 3, kind: 'lazy' },
      { from: 'view/index.ts', to: 'view/b.ts', line: 1, kind: 'static' },
      { from: 'view/b.ts', to: 'view/c.ts', line: 1, kind: 'static' },
      { from: 'view/c.ts', to: 'view/index.ts', line: 1, kind: 'static' },
      { from: 'core/x.ts', to: 'core/y.ts', line: 1, kind: 'type' }, // erased: no cycle at run time
      { from: 'core/y.ts', to: 'core/x.ts', line: 1, kind: 'static' },
    ];
    expect(wrongArrows(example, AREAS)).toEqual([
      'core/a.ts:1: core imports view (view/index.ts)',
      'studio/a.ts:2: imports view/camera.ts, not a door of view',
    ]);
    expect(cycles(example)).toEqual([['view/b.ts', 'view/c.ts', 'view/index.ts', 'view/b.ts']]);
  });
});
