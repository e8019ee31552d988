// The view options: how the plant is meshed (sides, smooth all) and shown (grid, lighting,
// textures, projection, colour by production). One object holds them; the view tools render from
// it, the view, the preview and the context view follow it, and a share link carries it.
import type { SharedState } from '../../share';
import { DEFAULT_LINE_WIDTH, LINE_WIDTH_MAX, LINE_WIDTH_MIN, type ProjectionMode, type RenderMode } from '../../view';

/** Every view option's value. */
export interface ViewOptionValues {
  /** Sides of each branch tube. */
  sides: number;
  /** Every axis drawn as a smooth curve, not only those the grammar marks. */
  smoothAll: boolean;
  /** The ground grid shown. */
  grid: boolean;
  /** The plant lit and shaded (off: the palette's colours as they are). */
  lighting: boolean;
  /** Bark and leaf textures on the plant. */
  textures: boolean;
  /** How the projection is chosen: from the plant (`auto`), or fixed. */
  projection: ProjectionMode;
  /** Every module coloured by the production that wrote it. */
  byProduction: boolean;
  /** How branches are drawn: lines, tubes, or from the plant (`auto`: lines for flat plants). */
  render: RenderMode;
  /** The width of the lines in the Lines mode, in CSS pixels. */
  lineWidth: number;
}

/** The name of one view option. */
export type ViewOption = keyof ViewOptionValues;

/** The view options of a share link (`SharedState['view']`). */
export type SharedViewOptions = NonNullable<SharedState['view']>;

/** The options a studio opens with. */
export const DEFAULT_VIEW_OPTIONS: Readonly<ViewOptionValues> = {
  sides: 6,
  smoothAll: false,
  grid: true,
  lighting: true,
  textures: true,
  projection: 'auto',
  byProduction: false,
  render: 'auto',
  lineWidth: DEFAULT_LINE_WIDTH,
};

const PROJECTION_MODES: readonly unknown[] = ['auto', 'perspective', 'orthographic'] satisfies ProjectionMode[];
const RENDER_MODES: readonly unknown[] = ['auto', 'lines', 'tubes'] satisfies RenderMode[];

/**
 * What a build for the render mode `render` asks of the mesh's tubes (`BuildOptions.tubes`): none
 * in the Lines mode, none for a flat plant in `auto` (drawn as lines), and tubes in the Tubes mode.
 * Switching to a mode that shows tubes builds them (the options change).
 */
export function tubesFor(render: RenderMode): boolean | 'unlessFlat' {
  return render === 'lines' ? false : render === 'auto' ? 'unlessFlat' : true;
}

/** Called after options changed, with all the values and the names of those that changed. */
export type ViewOptionsListener = (values: Readonly<ViewOptionValues>, changed: ReadonlySet<ViewOption>) => void;

/** The view options in force: the single source of truth for them on the page. */
export class ViewOptions {
  private current: ViewOptionValues = { ...DEFAULT_VIEW_OPTIONS };
  private readonly listeners = new Set<ViewOptionsListener>();

  /** `sidesChoices`: the numbers of sides offered (any other is refused). */
  constructor(private readonly sidesChoices: readonly number[]) {}

  /** The options now. */
  get values(): Readonly<ViewOptionValues> {
    return this.current;
  }

  /** Calls `listener` after every change; returns the function that stops it. */
  onChange(listener: ViewOptionsListener): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  /**
   * Changes the options given. A value of the wrong kind (sides not offered, a projection that is
   * none) is ignored; listeners hear of the options whose value changed, if any did.
   */
  set(change: Partial<ViewOptionValues>): void {
    const next = { ...this.current };
    const changed = new Set<ViewOption>();
    for (const [name, value] of Object.entries(change) as [ViewOption, unknown][]) {
      if (!this.accepts(name, value) || next[name] === value) continue;
      (next as Record<ViewOption, unknown>)[name] = value;
      changed.add(name);
    }
    if (changed.size === 0) return;
    this.current = next;
    for (const listener of this.listeners) listener(next, changed);
  }

  /** The options as a share link holds them (textures are not part of a link). */
  toShared(): SharedViewOptions {
    const { sides, smoothAll, byProduction, grid, lighting, projection, render, lineWidth } = this.current;
    return { sides, smoothAll, byProduction, grid, lighting, projection, render, lineWidth };
  }

  /** Applies a link's options: those it gives and that are valid; the others stay as they are. */
  applyShared(view: SharedState['view']): void {
    const { sides, smoothAll, byProduction, grid, lighting, projection, render, lineWidth } = view ?? {};
    this.set({ sides, smoothAll, byProduction, grid, lighting, projection, render, lineWidth }); // absent ones are ignored
  }

  private accepts(name: ViewOption, value: unknown): boolean {
    switch (name) {
      case 'sides':
        return this.sidesChoices.includes(value as number);
      case 'projection':
        return PROJECTION_MODES.includes(value);
      case 'render':
        return RENDER_MODES.includes(value);
      case 'lineWidth':
        return typeof value === 'number' && value >= LINE_WIDTH_MIN && value <= LINE_WIDTH_MAX;
      case 'smoothAll':
      case 'grid':
      case 'lighting':
      case 'textures':
      case 'byProduction':
        return typeof value === 'boolean';
      default:
        return false; // not a view option
    }
  }
}
