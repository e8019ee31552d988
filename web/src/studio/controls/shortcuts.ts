// The studio's keyboard shortcuts: one table, which drives both the key handler and the help.
// All but F1 (help, as everywhere) use Alt with a key the editor and browsers leave free (Alt with
// F, E, D, V, S, B, T, H or a digit opens browser menus or tabs on some systems), and work wherever
// the focus is.

/** What a shortcut does. */
export type ShortcutAction = 'stepBack' | 'stepForward' | 'playPause' | 'reroll' | 'gallery' | 'frame' | 'projection' | 'stages' | 'help' | 'fullscreen' | 'large';

/** One shortcut: the key (`KeyboardEvent.code`, with Alt unless `plain`), how it is written, what it does. */
export interface Shortcut {
  code: string;
  /** The key alone, without Alt (F1). */
  plain?: true;
  keys: string;
  action: ShortcutAction;
  description: string;
}

export const SHORTCUTS: readonly Shortcut[] = [
  { code: 'Comma', keys: 'Alt+,', action: 'stepBack', description: 'One iteration fewer' },
  { code: 'Period', keys: 'Alt+.', action: 'stepForward', description: 'One iteration more' },
  { code: 'KeyP', keys: 'Alt+P', action: 'playPause', description: 'Play the growth / pause (the timeline under the view)' },
  { code: 'KeyR', keys: 'Alt+R', action: 'reroll', description: 'New random seed' },
  { code: 'KeyG', keys: 'Alt+G', action: 'gallery', description: 'Open the gallery' },
  { code: 'KeyK', keys: 'Alt+K', action: 'frame', description: 'Frame the plant' },
  { code: 'KeyO', keys: 'Alt+O', action: 'projection', description: 'Switch between the 2D and the 3D view' },
  { code: 'KeyA', keys: 'Alt+A', action: 'stages', description: 'Stages: the iterations side by side' },
  { code: 'Enter', keys: 'Alt+Enter', action: 'fullscreen', description: 'Fullscreen: the plant alone (Escape returns)' },
  { code: 'KeyL', keys: 'Alt+L', action: 'large', description: 'Large: for a projector' },
  { code: 'F1', plain: true, keys: 'F1', action: 'help', description: 'The language reference (Help)' },
];

/** The action of a key event, if it is one of the shortcuts (Alt alone as modifier, or no modifier for a plain one). */
export function shortcutFor(event: Pick<KeyboardEvent, 'code' | 'altKey' | 'ctrlKey' | 'metaKey' | 'shiftKey'>): Shortcut | undefined {
  if (event.ctrlKey || event.metaKey || event.shiftKey) return undefined;
  return SHORTCUTS.find((s) => s.code === event.code && event.altKey !== (s.plain === true));
}

/** Runs the actions on their keys anywhere on the page (before the editor sees them). */
export function installShortcuts(target: Window, run: (action: ShortcutAction) => void): void {
  target.addEventListener(
    'keydown',
    (event) => {
      const shortcut = shortcutFor(event);
      if (!shortcut || event.repeat) return;
      event.preventDefault();
      event.stopPropagation();
      run(shortcut.action);
    },
    { capture: true },
  );
}

/** Fills a help list (`<dl>`) with the shortcuts and the other keys worth knowing. */
export function renderShortcutHelp(list: HTMLElement): void {
  const rows: [string, string][] = [
    ...SHORTCUTS.map((s): [string, string] => [s.keys, s.description]),
    ['Ctrl+O', 'Open a grammar file (or drop one on the page)'],
    ['Ctrl+S', 'Save the grammar as a .lsys file'],
    ['Ctrl+Space', 'Complete a directive, command or #define name'],
    ['Ctrl+Shift+M', 'List every error and warning in full, under the text (Problems)'],
    ['Ctrl+Z', 'Undo, also an example, file or saved grammar opened over your text'],
    ['← → on the divider', 'Resize the editor and the view'],
    ['Space on the view or the timeline', 'Play the growth / pause'],
    ['← → on the timeline', 'A step of growth back or on (Shift: a tenth of a step); Home / End: the range’s ends'],
  ];
  list.replaceChildren(
    ...rows.flatMap(([keys, description]) => {
      const term = document.createElement('dt');
      for (const [i, key] of keys.split('+').entries()) {
        if (i > 0) term.append('+');
        const kbd = document.createElement('kbd');
        kbd.textContent = key;
        term.append(kbd);
      }
      const detail = document.createElement('dd');
      detail.textContent = description;
      return [term, detail];
    }),
  );
}
