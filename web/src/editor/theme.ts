// The editor's look: fills its pane, follows the page's colour scheme through CSS variables.
import { EditorView } from '@codemirror/view';

/** Editor theme; the colours live in styles/page.css so `prefers-color-scheme` switches them. */
export const studioEditorTheme = EditorView.theme({
  '&': {
    height: '100%',
    fontSize: 'var(--editor-font-size, 14px)',
    color: 'var(--text)',
    backgroundColor: 'var(--editor-bg)',
  },
  '.cm-scroller': {
    fontFamily: 'ui-monospace, SFMono-Regular, Menlo, Consolas, "Liberation Mono", monospace',
    lineHeight: '1.55',
  },
  '.cm-content': { caretColor: 'var(--text)' },
  '.cm-cursor, .cm-dropCursor': { borderLeftColor: 'var(--text)' },
  '.cm-gutters': {
    backgroundColor: 'var(--editor-gutter)',
    color: 'var(--muted)',
    borderRight: '1px solid var(--border)',
  },
  '.cm-surface-marker, .cm-curve-marker': { color: 'var(--accent)', cursor: 'pointer', padding: '0 2px' },
  '.cm-activeLine, .cm-activeLineGutter': { backgroundColor: 'var(--editor-active-line)' },
  '&.cm-focused .cm-selectionBackground, .cm-selectionBackground, ::selection': {
    backgroundColor: 'var(--editor-selection)',
  },
  '&.cm-focused': { outline: 'none' },
  '.cm-command-doc': {
    padding: '4px 8px',
    fontFamily: 'system-ui, sans-serif',
    fontSize: '13px',
  },
  '.cm-reference-link': {
    padding: '0',
    border: 'none',
    background: 'none',
    color: 'var(--focus)',
    fontWeight: '600',
    textDecoration: 'underline',
    cursor: 'pointer',
  },
  '.cm-tooltip': {
    backgroundColor: 'var(--panel)',
    color: 'var(--text)',
    border: '1px solid var(--border)',
  },
  // Panels under the text (the list of problems, search) in the page's colours, not CodeMirror's
  // light grey, which was a bright strip in the dark scheme.
  '.cm-panels': { backgroundColor: 'var(--panel)', color: 'var(--text)' },
  '.cm-panels.cm-panels-bottom': { borderTop: '1px solid var(--border)' },
  // (The list of problems has its own styles: problems-panel.css.)
  // A diagnostic's code (E0109) at full strength: CodeMirror's 0.7 opacity left it at 3.1:1 on the
  // list's selected row (axe, WCAG AA wants 4.5:1); its smaller size keeps it secondary.
  '.cm-diagnosticSource': { opacity: 1 },
});
