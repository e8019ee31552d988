import { describe, expect, it } from 'vitest';
import { growthAttributes } from './embed-plant';

/** An element with `attributes` (name → value; '' for a bare attribute). */
const element = (attributes: Record<string, string>) => ({
  getAttribute: (name: string) => attributes[name] ?? null,
  hasAttribute: (name: string) => name in attributes,
});

describe('<meristem-plant> growth attributes (and embed.html’s query)', () => {
  it('animate, loop and speed ask for the growth played', () => {
    expect(growthAttributes(element({ animate: '', loop: '', speed: '1' }))).toEqual({ playing: true, loop: true, speed: 1 });
    expect(growthAttributes(element({ t: '2.5', from: '1', to: '3' }))).toEqual({ t: 2.5, from: 1, to: 3, playing: false, loop: false });
  });

  it('is nothing without any of them', () => {
    expect(growthAttributes(element({ src: 'fern.lsys', iterations: '5' }))).toBeUndefined();
  });

  it('clamps or drops what a hostile page writes', () => {
    expect(growthAttributes(element({ animate: '', speed: '1e9', t: '-5', to: 'soon' }))).toEqual({ playing: true, loop: false, speed: 20, t: 0 });
  });
});
