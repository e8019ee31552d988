// The grammar editor's way into the editors of what a line declares: a marker in the gutter of
// every line that declares a surface (`#surface X …`, `#patch X …`) or a curve function (`#curve
// NAME …`, `#table NAME …`), which opens the surface editor on X or the curve editor on NAME when
// pressed, and Alt+B (B for Bézier, and B-spline) on such a line, from the keyboard.
import { gutter, GutterMarker, keymap, type EditorView } from '@codemirror/view';
import { RangeSet, type Extension, type Text } from '@codemirror/state';
import type { EditorTarget, OpenEditor } from './grammar-text';
import { curveNameOf, surfaceLetterOf } from './surface-lines';

/** The key that opens the editor of the cursor's line. */
export const SURFACE_KEY = 'Alt-b';

class EditorTargetMarker extends GutterMarker {
  constructor(readonly target: EditorTarget) {
    super();
  }

  override eq(other: GutterMarker): boolean {
    return other instanceof EditorTargetMarker && other.target.what === this.target.what && other.target.name === this.target.name;
  }

  override toDOM(): Node {
    const { what, name } = this.target;
    const marker = document.createElement('span');
    marker.className = `cm-${what}-marker`;
    marker.textContent = what === 'surface' ? '◆' : '∿';
    marker.title = what === 'surface' ? `Edit the surface ~${name} (Alt+B on this line)` : `Edit the curve ${name} (Alt+B on this line)`;
    marker.dataset.testid = `${what}-marker-${name}`;
    return marker;
  }
}

/** What the line `text` declares that an editor edits, or null. */
function editableOf(text: string): EditorTarget | null {
  if (!text.includes('#')) return null;
  const letter = surfaceLetterOf(text);
  if (letter !== null) return { what: 'surface', name: letter };
  const name = curveNameOf(text);
  return name === null ? null : { what: 'curve', name };
}

/**
 * The markers of the lines of `doc` that declare surfaces or curves, made again on every edit: the
 * lines read in one pass (looking each up by its number, `doc.line(n)`, took 40–90 ms a keystroke
 * in a text of 100,000 lines: issue 50).
 */
export function markers(doc: Text): RangeSet<GutterMarker> {
  const ranges = [];
  let from = 0;
  for (const text of doc.iterLines()) {
    const target = editableOf(text);
    if (target) ranges.push(new EditorTargetMarker(target).range(from));
    from += text.length + 1; // (a line break is one position in CodeMirror's text, whatever it was)
  }
  return RangeSet.of(ranges);
}

/** Opens the editor of the line at `pos`; false when it declares nothing an editor edits. */
function openAt(view: EditorView, pos: number, open: OpenEditor): boolean {
  const target = editableOf(view.state.doc.lineAt(pos).text);
  if (target) open(target);
  return target !== null;
}

/** The gutter's markers and the key, which call `open` with a surface's letter or a curve's name. */
export function surfaceGutter(open: OpenEditor): Extension {
  let cached: { doc: Text; set: RangeSet<GutterMarker> } | undefined;
  return [
    gutter({
      class: 'cm-surface-gutter',
      markers: (view) => {
        if (cached?.doc !== view.state.doc) cached = { doc: view.state.doc, set: markers(view.state.doc) };
        return cached.set;
      },
      domEventHandlers: {
        mousedown: (view, line) => openAt(view, line.from, open),
      },
    }),
    keymap.of([{ key: SURFACE_KEY, run: (view) => openAt(view, view.state.selection.main.head, open) }]),
  ];
}
