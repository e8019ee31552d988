// The course (public/lessons/*.md) against the real core: every lesson file reads, every grammar
// builds without a diagnostic, and every task's check fails on the grammar it starts from and passes
// on its solution, evaluated as the Learn panel does (lesson-check.ts on the build's stats and module
// texts). So no lesson can ship broken. Also: the lesson files' format, and its errors with the line.
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { LessonFileError, lessonIndex, readLesson, readLessons } from '../../scripts/lesson-files';
import { lessonAssets } from '../../scripts/lessons-plugin';
import { directiveOfKind, inspectPlant, loadVocabulary, writtenDirective } from '../../web/src/core';
import { evaluateCheck, parseCheck, plantFacts, spokenAnswer } from '../../web/src/studio/learn/lesson-check';
import { compareLessons, isLesson, isLessonIndex } from '../../web/src/studio/learn/lesson-manifest';
import { writtenSeed } from '../../web/src/studio/learn/written-seed';

const LESSONS_DIR = fileURLToPath(new URL('../../public/lessons', import.meta.url));
const lessons = readLessons(LESSONS_DIR);

/** The check's answer on `source`, as the Learn panel says it. */
async function answer(check: string, source: string, seed?: number): Promise<{ pass: boolean; said: string }> {
  const parsed = parseCheck(check);
  if (!parsed.ok) throw new Error(parsed.error.message);
  const { build, inspector } = inspectPlant(source, seed === undefined ? {} : { seed });
  try {
    expect([...build.diagnostics], source).toEqual([]);
    const seedDirective = writtenDirective(directiveOfKind(await loadVocabulary(), 'Seed'));
    const facts = await plantFacts(parsed.check, build, inspector, writtenSeed(source, seedDirective));
    if (!facts.ok) throw new Error(facts.reason);
    const result = evaluateCheck(parsed.check, facts.facts);
    return { pass: result.pass, said: spokenAnswer(result) };
  } finally {
    inspector.free();
  }
}

describe('the course', () => {
  it('follows ABOP chapter 1 in at least 8 lessons, chapters 2 to 6 and the environment in at least 3 each, in order, each with a grammar and a task', () => {
    const inChapter = (chapter: string) => lessons.filter((l) => l.chapter === chapter).length;
    expect(inChapter('1')).toBeGreaterThanOrEqual(8);
    expect(inChapter('2')).toBeGreaterThanOrEqual(3);
    expect(inChapter('6')).toBeGreaterThanOrEqual(3);
    expect(inChapter('3')).toBeGreaterThanOrEqual(3);
    expect(inChapter('4')).toBeGreaterThanOrEqual(3);
    expect(inChapter('5')).toBeGreaterThanOrEqual(3);
    // Issue 47: a tree towards light and in the dark, trees in a row, a sheared hedge.
    expect(inChapter('Environment: open L-systems')).toBeGreaterThanOrEqual(3);
    expect(lessons.map((l) => l.slug)).toEqual([...lessons].sort(compareLessons).map((l) => l.slug));
    for (const lesson of lessons) {
      expect(lesson.grammars.length, lesson.slug).toBeGreaterThan(0);
      expect(lesson.tasks.length, lesson.slug).toBeGreaterThan(0);
      expect(isLesson(JSON.parse(JSON.stringify(lesson))), lesson.slug).toBe(true);
    }
    expect(isLessonIndex(JSON.parse(JSON.stringify(lessonIndex(lessons))))).toBe(true);
  });

  it('emits the list and one file per lesson, with relative paths', () => {
    const assets = lessonAssets(LESSONS_DIR);
    expect([...assets.keys()].sort()).toEqual(['lessons/index.json', ...lessons.map((l) => `lessons/${l.slug}.json`)].sort());
  });

  describe.each(lessons.map((l) => [l.slug, l] as const))('%s', (_, lesson) => {
    it.each(lesson.grammars.map((g) => [g.title, g.text]))('builds %s without a diagnostic', (_title, text) => {
      const { build, inspector } = inspectPlant(text);
      inspector.free();
      expect([...build.diagnostics]).toEqual([]);
      expect(build.stats.segments).toBeGreaterThan(0);
    });

    it.each(lesson.tasks.map((t, i) => [i + 1, t] as const))('task %i fails on its starting grammar and passes on its solution', async (_n, task) => {
      const start = await answer(task.check, lesson.grammars[task.start].text);
      expect(start.pass, start.said).toBe(false);
      expect(start.said).toMatch(/^Not yet: /);
      const solution = await answer(task.check, task.solution);
      expect(solution.pass, solution.said).toBe(true);
    });
  });
});

describe('a lesson file', () => {
  const good = ['---', 'title: T', 'chapter: 1', 'order: 2', '---', '', '# Head', '', 'Text [a](pic.png) ![b](img/x.png) [c](https://example.org/)', '', '```lsys', '// My grammar', 'axiom: F', '```', '', '```task', 'Do *this*.', 'check: segments > 1', 'hint: more', 'solution:', 'axiom: FF', '```', ''];

  function problem(lines: string[]): string {
    try {
      readLesson('public/lessons/t.md', lines.join('\n'));
    } catch (error) {
      if (error instanceof LessonFileError) return error.message;
      throw error;
    }
    return 'no error';
  }

  it('is read into HTML with placeholders, grammars and tasks', () => {
    const lesson = readLesson('public/lessons/t.md', good.join('\n'));
    expect(lesson).toMatchObject({ slug: 't', title: 'T', chapter: '1', order: 2, section: '' });
    expect(lesson.html).toContain('<h3>Head</h3>');
    expect(lesson.html).toContain('<div class="lesson-grammar" data-grammar="0"></div>');
    expect(lesson.html).toContain('<div class="lesson-task" data-task="0"></div>');
    expect(lesson.html).toContain('href="lessons/pic.png"');
    expect(lesson.html).toContain('src="lessons/img/x.png"');
    expect(lesson.html).toContain('href="https://example.org/"');
    expect(lesson.grammars).toEqual([{ title: 'My grammar', text: '// My grammar\naxiom: F\n' }]);
    expect(lesson.tasks).toEqual([{ html: '<p>Do <em>this</em>.</p>\n', check: 'segments > 1', hint: 'more', solution: 'axiom: FF\n', start: 0 }]);
  });

  it.each([
    ['no front matter', good.slice(5), 'public/lessons/t.md:1: a lesson starts with front matter'],
    ['a missing title', good.filter((l) => !l.startsWith('title')), 'public/lessons/t.md:1: the front matter needs title:'],
    ['an unknown key', good.map((l) => (l === 'order: 2' ? 'ordre: 2' : l)), 'public/lessons/t.md:4: unknown front matter key "ordre"'],
    ['a malformed check', good.map((l) => (l.startsWith('check') ? 'check: segmnts > 1' : l)), 'public/lessons/t.md:18: check: "segmnts" is not a fact'],
    ['a check that is no comparison', good.map((l) => (l.startsWith('check') ? 'check: count("F")' : l)), 'public/lessons/t.md:18: check: count("F") is a number: compare it'],
    ['no check', good.filter((l) => !l.startsWith('check')), 'public/lessons/t.md:16: a task needs a check: line'],
    ['no solution', good.filter((l) => !l.startsWith('solution')), 'public/lessons/t.md:16: a task needs a solution:'],
    ['no grammar before the task', good.slice(0, 10).concat(good.slice(14)), 'public/lessons/t.md:12: a task starts from a grammar'],
    ['a grammar inside a list', good.slice(0, 10).concat(['- item', '', '  ```lsys', '  axiom: F', '  ```']), 'stand on their own'],
  ])('with %s fails with its line', (_, lines, message) => {
    expect(problem(lines)).toContain(message);
  });
});

describe('the chapter 1 checks accept every correct answer and only those', () => {
  const lesson = (slug: string) => lessons.find((l) => l.slug === slug)!;
  const filament = (axiom: string, n: number, rules: string) => `#iterations ${n}\naxiom: ${axiom}\n${rules}\nhomomorphism:\na -> F\nb -> F[+F][-F]\n`;

  it('lesson 6 takes a right-to-left signal on a filament of any length at any step', async () => {
    const { check } = lesson('06-signals').tasks[0];
    const right = 'a > b -> b\nb -> a';
    for (const [axiom, n] of [['aaaaaaab', 3], ['aaaaaaab', 4], ['aaaaaaab', 7], ['aaaaaaaab', 5], ['aaab', 2], ['aaaaaaaaaaaab', 10]] as const) {
      const said = await answer(check, filament(axiom, n, right));
      expect(said.pass, `${axiom} at ${n}: ${said.said}`).toBe(true);
    }
    // The other way round, rules in the other order and a right context over any neighbour pass too.
    expect((await answer(check, filament('aaaaaaab', 4, 'b -> a\na > b -> b'))).pass).toBe(true);
    for (const [axiom, n, rules] of [
      ['baaaaaaaa', 3, 'b < a -> b\nb -> a'], // the signal still goes left to right
      ['aaaaaaab', 3, 'b < a -> b\nb -> a'], // a left context at the right end: the signal is lost
      ['aaaaaaab', 3, 'a > b -> b'], // b stays: a trail of b
      ['aaaaaaab', 3, 'b -> a'], // no signal at all
      ['aaab', 5, 'a > b -> b\nb -> a'], // run off the left end
    ] as const) {
      const said = await answer(check, filament(axiom, n, rules));
      expect(said.pass, `${axiom} at ${n} with ${rules}: ${said.said}`).toBe(false);
    }
  });

  it('lesson 5 wants the seed in the text, not only in the Seed box', async () => {
    const task = lesson('05-stochastic').tasks[0];
    const start = lesson('05-stochastic').grammars[task.start].text;
    const tall = Number(/#seed (\d+)/.exec(task.solution)![1]);
    // The tall plant from the Seed box, with the text still saying #seed 1: not yet.
    const boxOnly = await answer(task.check, start, tall);
    expect(boxOnly.pass, boxOnly.said).toBe(false);
    expect(boxOnly.said).toContain('text_seed is 1');
    // The seed written into the text passes with the box empty or holding the same seed…
    expect((await answer(task.check, task.solution)).pass).toBe(true);
    expect((await answer(task.check, task.solution, tall)).pass).toBe(true);
    // …but not while the box overrides it with another, nor with the #seed line removed.
    expect((await answer(task.check, task.solution, tall + 1)).pass).toBe(false);
    expect((await answer(task.check, task.solution.replace(/#seed \d+\n/, ''), tall)).pass).toBe(false);
  });
});

describe('the parastichy facts', () => {
  it('refuse a plant of more spheres than they read, in words', async () => {
    const parsed = parseCheck('parastichies_m == 34');
    if (!parsed.ok) throw new Error(parsed.error.message);
    const { build, inspector } = inspectPlant('#iterations 13\naxiom: A\nA -> AA\nhomomorphism:\nA -> [@O(0.1)]f\n');
    try {
      const facts = await plantFacts(parsed.check, build, inspector);
      expect(facts).toEqual({ ok: false, reason: 'the plant has 8,192 spheres, more than the parastichy count reads (5,000); try fewer iterations' });
    } finally {
      inspector.free();
    }
  });
});

describe('the trunk\'s proportion', () => {
  it('is measured on the first tube drawn, and refused in words when the plant has none', async () => {
    const parsed = parseCheck('trunk_width_ratio > 0.1');
    if (!parsed.ok) throw new Error(parsed.error.message);
    // A trunk 2 wide (#width_unit 1) under a plant 10 tall: 0.2.
    const { build, inspector } = inspectPlant('#width_unit 1\naxiom: !(2)F(4)!(1)F(6)\n');
    try {
      const facts = await plantFacts(parsed.check, build, inspector);
      if (!facts.ok) throw new Error(facts.reason);
      expect(facts.facts.trunkWidthRatio).toBeCloseTo(0.2, 3);
      const lines = { ...build, mesh: { ...build.mesh, indices: new Uint32Array(), ranges: new Uint32Array() } };
      const refused = await plantFacts(parsed.check, lines, inspector);
      expect(refused.ok).toBe(false);
      if (!refused.ok) expect(refused.reason).toContain('choose Tubes');
    } finally {
      inspector.free();
    }
  });
});
