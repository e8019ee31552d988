// The draggable, keyboard-accessible separator between the editor and the view. It sets the
// editor column's share of the width as the CSS variable `--editor-share` on the studio element
// and remembers it in localStorage. On narrow screens (stacked layout) CSS hides it.

/** The editor's share of the width is kept within these bounds. */
export const MIN_SHARE = 0.15;
export const MAX_SHARE = 0.85;
/** The share at first visit and after a double-click. */
export const DEFAULT_SHARE = 0.4;
const STORAGE_KEY = 'meristem.editorShare';

/** `share` kept within [MIN_SHARE, MAX_SHARE]; not-a-number gives the default. */
export function clampShare(share: number): number {
  if (!Number.isFinite(share)) return DEFAULT_SHARE;
  return Math.min(MAX_SHARE, Math.max(MIN_SHARE, share));
}

/**
 * The share after a key on the focused separator (the ARIA window-splitter pattern): arrows move by
 * 2 %, Page Up/Down by 10 %, Home/End go to the ends, Enter restores the default. Undefined for
 * other keys.
 */
export function shareAfterKey(share: number, key: string): number | undefined {
  const moves: Record<string, number> = { ArrowLeft: -0.02, ArrowRight: 0.02, PageDown: -0.1, PageUp: 0.1 };
  if (key in moves) return clampShare(share + moves[key]);
  if (key === 'Home') return MIN_SHARE;
  if (key === 'End') return MAX_SHARE;
  if (key === 'Enter') return DEFAULT_SHARE;
  return undefined;
}

/** Makes `separator` resize the columns of `studio`. */
export function attachSplitter(separator: HTMLElement, studio: HTMLElement): void {
  let share = clampShare(Number(localStorage.getItem(STORAGE_KEY) ?? DEFAULT_SHARE));
  const apply = (next: number, remember: boolean) => {
    share = clampShare(next);
    studio.style.setProperty('--editor-share', String(share));
    separator.setAttribute('aria-valuenow', String(Math.round(share * 100)));
    separator.setAttribute('aria-valuetext', `editor ${Math.round(share * 100)} % of the width`);
    if (remember) localStorage.setItem(STORAGE_KEY, String(share));
  };
  separator.setAttribute('aria-valuemin', String(MIN_SHARE * 100));
  separator.setAttribute('aria-valuemax', String(MAX_SHARE * 100));
  apply(share, false);

  separator.addEventListener('keydown', (event) => {
    const next = shareAfterKey(share, event.key);
    if (next === undefined) return;
    event.preventDefault();
    apply(next, true);
  });
  separator.addEventListener('dblclick', () => apply(DEFAULT_SHARE, true));
  separator.addEventListener('pointerdown', (event) => {
    if (event.button !== 0) return;
    event.preventDefault();
    separator.setPointerCapture(event.pointerId);
    separator.focus();
    studio.classList.add('resizing');
    const box = studio.getBoundingClientRect();
    const move = (e: PointerEvent) => apply((e.clientX - box.left) / box.width, false);
    const end = () => {
      separator.removeEventListener('pointermove', move);
      separator.removeEventListener('pointerup', end);
      separator.removeEventListener('pointercancel', end);
      studio.classList.remove('resizing');
      apply(share, true);
    };
    separator.addEventListener('pointermove', move);
    separator.addEventListener('pointerup', end);
    separator.addEventListener('pointercancel', end);
  });
}
