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

describe('embed snippets of a growing plant', () => {
  const growth = { t: 2.5, speed: 0.5, loop: true, from: 1, to: 3 };

  it('play the growth as the timeline did: animate, loop, speed and range', () => {
    expect(frameSnippet(SITE, '#s=1.abc', { iterations: false, sliders: false }, growth)).toContain(
      'src="https://example.org/courses/meristem/embed.html?animate&amp;loop&amp;speed=0.5&amp;from=1&amp;to=3#s=1.abc"',
    );
    const html = elementSnippet(SITE, { text: 'axiom: F', growth }, { iterations: true, sliders: false });
    expect(html).toContain('<meristem-plant controls="iterations" animate loop speed="0.5" from="1" to="3" style="height: 420px">');
  });

  it('do not animate a plant whose timeline was not used', () => {
    expect(frameSnippet(SITE, '#s=1.abc', { iterations: false, sliders: false }, { speed: 1 })).toContain('embed.html#s=1.abc');
    expect(elementSnippet(SITE, { text: 'axiom: F', growth: { speed: 2 } }, { iterations: false, sliders: false })).toContain('<meristem-plant style=');
  });

  it('frames the studio itself for variants, which opens with them side by side', () => {
    const html = frameSnippet(SITE, '#s=1.abc', { iterations: true, sliders: false }, undefined, true);
    expect(html).toContain('src="https://example.org/courses/meristem/#s=1.abc"');
    expect(html).not.toContain('embed.html');
  });

  it('writes a row of captioned elements for variants, each its own grammar and seed, escaped', () => {
    const variants = [
      { text: '#define a 20\naxiom: F', caption: 'a = 20' },
      { text: '#define a 25\naxiom: F', caption: '<b>a</b> = 25', seed: 4 },
      { text: '// </meristem-plant></figure><script>x</script>', iterations: 2 },
    ];
    const html = elementSnippet(SITE, { text: variants[0].text, variants }, { iterations: false, sliders: false });
    expect(html.match(/<meristem-plant\b/g)).toHaveLength(3);
    expect(html.match(/<\/meristem-plant>/g)).toHaveLength(3);
    expect(html.match(/<\/figure>/g)).toHaveLength(3);
    expect(html.match(/<script\b/g), 'only the loader').toHaveLength(1);
    expect(html).toContain('<meristem-plant seed="4" style="height: 360px">\n#define a 25\naxiom: F\n');
    expect(html).toContain('<meristem-plant iterations="2" style="height: 360px">');
    expect([...html.matchAll(/<figcaption[^>]*>([^<]*)<\/figcaption>/g)].map((m) => m[1])).toEqual(['a = 20', '&lt;b&gt;a&lt;/b&gt; = 25', 'plant 3']);
  });
});
