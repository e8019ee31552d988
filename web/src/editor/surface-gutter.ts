// The grammar editor's way into the surface editor: a marker in the gutter of every line that
// declares a surface (`#surface X …`, `#patch X …`), which opens the editor on surface X when
// pressed, and Alt+B (B for Bézier) on such a line, from the keyboard.
import { gutter, GutterMarker, keymap, type EditorView } from '@codemirror/view';
import { RangeSet, type Extension, type Text } from '@codemirror/state';
import { surfaceLetterOf } from './surface-lines';

/** The key that opens the surface editor on the cursor's line. */
export const SURFACE_KEY = 'Alt-b';

class SurfaceMarker extends GutterMarker {
  constructor(readonly letter: string) {
    super();
  }

  override eq(other: GutterMarker): boolean {
    return other instanceof SurfaceMarker && other.letter === this.letter;
  }

  override toDOM(): Node {
    const marker = document.createElement('span');
    marker.className = 'cm-surface-marker';
    marker.textContent = '◆';
    marker.title = `Edit the surface ~${this.letter} (Alt+B on this line)`;
    marker.dataset.testid = `surface-marker-${this.letter}`;
    return marker;
  }
}

/** The markers of the lines of `doc` that declare surfaces. */
function markers(doc: Text): RangeSet<GutterMarker> {
  const ranges = [];
  for (let n = 1; n <= doc.lines; n++) {
    const line = doc.line(n);
    if (!line.text.includes('#')) continue;
    const letter = surfaceLetterOf(line.text);
    if (letter !== null) ranges.push(new SurfaceMarker(letter).range(line.from));
  }
  return RangeSet.of(ranges);
}

/** The surface letter of the line at `pos`, or null. */
function letterAt(view: EditorView, pos: number): string | null {
  return surfaceLetterOf(view.state.doc.lineAt(pos).text);
}

/** The gutter's markers and the key, which call `open` with a surface's letter. */
export function surfaceGutter(open: (letter: string) => void): Extension {
  let cached: { doc: Text; set: RangeSet<GutterMarker> } | undefined;
  return [
    gutter({
      class: 'cm-surface-gutter',
      markers: (view) => {
        if (cached?.doc !== view.state.doc) cached = { doc: view.state.doc, set: markers(view.state.doc) };
        return cached.set;
      },
      domEventHandlers: {
        mousedown: (view, line) => {
          const letter = letterAt(view, line.from);
          if (letter === null) return false;
          open(letter);
          return true;
        },
      },
    }),
    keymap.of([
      {
        key: SURFACE_KEY,
        run: (view) => {
          const letter = letterAt(view, view.state.selection.main.head);
          if (letter === null) return false;
          open(letter);
          return true;
        },
      },
    ]),
  ];
}
