import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { languageVocabulary, writtenDirective } from '../web/src/core';
import { referenceAnchor } from '../web/src/editor/reference';
import { headingSlug, renderReference } from './reference-plugin';

const language = renderReference(readFileSync(new URL('../docs/LANGUAGE.md', import.meta.url), 'utf8'));
const unescape = (text: string) => text.replace(/&#(\d+);/g, (_, code: string) => String.fromCharCode(Number(code)));
const ids = (html: string) => [...html.matchAll(/ id="([^"]*)"/g)].map((m) => unescape(m[1]));

describe('the rendered language reference', () => {
  it('has a row for every module and directive of the vocabulary, which hover docs link to', () => {
    const vocabulary = languageVocabulary();
    const names = [...vocabulary.modules.map((m) => m.name), ...vocabulary.directives.map(writtenDirective)];
    const present = new Set(ids(language));
    expect(names.filter((name) => !present.has(referenceAnchor(name)))).toEqual([]);
  });

  it('gives every id once, and every link inside it a target', () => {
    const all = ids(language);
    expect(all.length).toBe(new Set(all).size);
    const targets = [...language.matchAll(/href="#([^"]*)"/g)].map((m) => unescape(m[1]));
    expect(targets.length).toBeGreaterThan(40);
    expect(targets.filter((t) => !all.includes(t))).toEqual([]);
  });

  it('anchors the names in the first cell of command and directive tables only, the first row naming one', () => {
    const html = renderReference(
      [
        '| command | what |', '| --- | --- |', '| `F` | forward |', '| `G` / `g` | `F` again |', '| `?P ?H` | queries |',
        '', '| directive | what |', '| --- | --- |', '| `#angle` | turn |', '| `F` | a second row for F |',
        '', '| feature | status |', '| --- | --- |', '| `#step` | yes |',
      ].join('\n'),
    );
    expect(ids(html)).toEqual(['ref-F', 'ref-G', 'ref-g', 'ref-?P', 'ref-?H', 'ref-angle']);
    expect(html).toContain('<td><code id="ref-G">G</code> / <code id="ref-g">g</code></td><td><code>F</code> again</td>');
    expect(html).toContain('<code>F</code></td><td>a second row for F');
  });

  it('gives headings GitHub’s ids, one level down, and lists the sections in its contents', () => {
    expect(headingSlug('`#lifetime MB VB [pu pm pl]`: which branches keep growing (section 2.1, equation 2)'.replaceAll('`', ''))).toBe(
      'lifetime-mb-vb-pu-pm-pl-which-branches-keep-growing-section-21-equation-2',
    );
    const html = renderReference('# Title\n\n## Growth: particle attributes\n\n### What a step does\n\n## Turtle\n\n## Turtle\n');
    expect(html).toContain('<h3 id="growth-particle-attributes">Growth: particle attributes</h3>');
    expect(html).toContain('<h4 id="what-a-step-does">');
    expect(ids(html)).toEqual(['title', 'growth-particle-attributes', 'what-a-step-does', 'turtle', 'turtle-1']);
    expect(html).toMatch(
      /<nav class="reference-toc".*<li><a href="#growth-particle-attributes">Growth: particle attributes<\/a><ol><li><a href="#what-a-step-does">What a step does<\/a><\/li><\/ol><\/li><li><a href="#turtle">Turtle<\/a><\/li>/,
    );
  });

  it('keeps the text as text: raw HTML escaped, links to repository files as their words', () => {
    const html = renderReference('A <script>alert(1)</script> and [the contract](../../shared/LANGUAGE.md), [a site](https://example.org/x), [above](#top).');
    expect(html).not.toContain('<script>');
    expect(html).toContain('&#60;script&#62;');
    expect(html).toContain('and the contract,');
    expect(html).toContain('<a href="https://example.org/x" target="_blank" rel="noopener noreferrer">a site</a>');
    expect(html).toContain('<a href="#top">above</a>');
  });
});
