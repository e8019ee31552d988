import { describe, expect, it } from 'vitest';
import { decodeState, encodeState } from '../../share';
import { DEFAULT_VIEW_OPTIONS, ViewOptions, tubesFor, type ViewOption, type ViewOptionValues } from './view-options';

const SIDES = [3, 4, 5, 6, 8, 12, 16, 24, 32];

/** View options and the changes their listeners heard of, one set of names per notification. */
function watched(): { options: ViewOptions; heard: ViewOption[][] } {
  const options = new ViewOptions(SIDES);
  const heard: ViewOption[][] = [];
  options.onChange((_, changed) => heard.push([...changed].sort()));
  return { options, heard };
}

describe('view options', () => {
  it('start at the defaults', () => {
    expect(new ViewOptions(SIDES).values).toEqual(DEFAULT_VIEW_OPTIONS);
  });

  it('survive a share link: serialised, encoded, decoded and applied to fresh options', async () => {
    const { options } = watched();
    const chosen: Omit<ViewOptionValues, 'textures'> = { sides: 12, smoothAll: true, byProduction: true, grid: false, lighting: false, projection: 'orthographic', render: 'tubes', lineWidth: 3.5 };
    options.set(chosen);
    const decoded = await decodeState(await encodeState({ text: 'axiom: F', view: options.toShared() }));
    if (!decoded.ok) throw new Error(decoded.error);
    const opened = new ViewOptions(SIDES);
    opened.applyShared(decoded.state.view);
    expect(opened.values).toEqual({ ...DEFAULT_VIEW_OPTIONS, ...chosen });
  });

  it('write the link fields in the order links have always had, and no textures', () => {
    expect(Object.keys(new ViewOptions(SIDES).toShared())).toEqual(['sides', 'smoothAll', 'byProduction', 'grid', 'lighting', 'projection', 'render', 'lineWidth']);
  });

  it('apply a link’s partial options and keep the others', () => {
    const { options, heard } = watched();
    options.set({ textures: false, sides: 8 });
    heard.length = 0;
    options.applyShared({ grid: false, projection: 'perspective' });
    expect(options.values).toEqual({ ...DEFAULT_VIEW_OPTIONS, textures: false, sides: 8, grid: false, projection: 'perspective' });
    expect(heard).toEqual([['grid', 'projection']]);
    options.applyShared(undefined);
    options.applyShared({});
    expect(heard).toHaveLength(1);
  });

  it('ignore invalid values (and keep the valid ones of the same change)', () => {
    const { options, heard } = watched();
    options.applyShared({ sides: 7, smoothAll: 'yes' as unknown as boolean, projection: 'fisheye' as 'auto', lighting: false, render: 'dots' as 'auto', lineWidth: 0.1 });
    options.set({ lineWidth: 21 });
    options.set({ grid: 1 as unknown as boolean, sides: Number.NaN, textures: null as unknown as boolean });
    options.set({ colour: true } as unknown as Partial<ViewOptionValues>);
    expect(options.values).toEqual({ ...DEFAULT_VIEW_OPTIONS, lighting: false });
    expect(heard).toEqual([['lighting']]);
  });

  it('tell listeners only of changes, until they stop listening', () => {
    const options = new ViewOptions(SIDES);
    const seen: Readonly<ViewOptionValues>[] = [];
    const stop = options.onChange((values) => seen.push(values));
    options.set({ grid: true, sides: 6 }); // as they are
    options.set({ grid: false });
    stop();
    options.set({ grid: true });
    expect(seen).toEqual([{ ...DEFAULT_VIEW_OPTIONS, grid: false }]);
  });
});

describe('tubesFor', () => {
  it('asks for no tubes in the Lines mode, none for flat plants in auto, and tubes in the Tubes mode', () => {
    expect(tubesFor('lines')).toBe(false);
    expect(tubesFor('auto')).toBe('unlessFlat');
    expect(tubesFor('tubes')).toBe(true);
  });
});
