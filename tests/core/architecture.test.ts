// The studio's side of crate/tests/architecture.rs: it reads every non-test file of web/src.
// - One boundary: only web/src/core/ imports the generated package (crate/pkg).
// - One vocabulary: the studio names no part of the language the core's vocabulary does not have,
//   and spells none of them for its logic. In the files' literals (strings, templates, regular
//   expressions; comments are skipped):
// - every directive (`#name`, three letters or more, not a colour) and every `@Name`, `?X`, `~x`
//   module a literal mentions is in the vocabulary;
// - no string literal is exactly a name (a directive, a module of two characters or more, a keyword
//   as written), and no regular expression contains one: code reads names from the vocabulary.
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join, relative } from 'node:path';
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
