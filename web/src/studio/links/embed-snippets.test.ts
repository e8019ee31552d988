import { describe, expect, it } from 'vitest';
import { elementSnippet, frameSnippet } from './embed-snippets';

const SITE = 'https://example.org/courses/meristem/';

describe('embed snippets', () => {
  it('frames embed.html of the site with the share state and the controls', () => {
    const html = frameSnippet(SITE, '#s=1.abc', { iterations: true, sliders: true });
    expect(html).toBe(
      '<iframe src="https://example.org/courses/meristem/embed.html?controls=iterations,sliders#s=1.abc" width="640" height="480" style="border: 0; max-width: 100%" title="A plant made with Meristem" allowfullscreen loading="lazy"></iframe>',
    );
    expect(frameSnippet(SITE, '#s=1.abc', { iterations: false, sliders: false })).toContain('src="https://example.org/courses/meristem/embed.html#s=1.abc"');
  });

  it('writes the grammar into the element as text, escaped, with its iterations and seed', () => {
    const html = elementSnippet(SITE, { text: 'axiom: A\nA -> B < C & D\n', iterations: 3, seed: 7 }, { iterations: true, sliders: false });
    expect(html).toBe(
      [
        '<script type="module" src="https://example.org/courses/meristem/meristem-plant.js"></script>',
        '<meristem-plant iterations="3" seed="7" controls="iterations" style="height: 420px">',
        'axiom: A',
        'A -&gt; B &lt; C &amp; D',
        '</meristem-plant>',
      ].join('\n'),
    );
  });

  it('cannot be closed early by the grammar', () => {
    const html = elementSnippet(SITE, { text: '// </meristem-plant><script>alert(1)</script>' }, { iterations: false, sliders: false });
    expect(html.match(/<\/meristem-plant>/g)).toHaveLength(1);
    expect(html).not.toContain('<script>alert');
  });
});
