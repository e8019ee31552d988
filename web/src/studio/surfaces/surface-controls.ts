// The surface editor's dialog, made (closed) in the page: a 3D view of the surface, the point
// chosen with its x, y, z, the drag's axis, and what the core says of the surface. Made here, not
// in index.html: it loads with the editor's code on first use.
import { el as make } from '../page/make-element';
import './surface-dialog.css';

/** The dialog's elements. */
export interface SurfaceControls {
  dialog: HTMLDialogElement;
  title: HTMLElement;
  letter: HTMLSelectElement;
  canvas: HTMLCanvasElement;
  status: HTMLElement;
  library: HTMLElement;
  writeOut: HTMLButtonElement;
  point: HTMLSelectElement;
  coordinates: [HTMLInputElement, HTMLInputElement, HTMLInputElement];
  axis: HTMLSelectElement;
  frame: HTMLButtonElement;
  close: HTMLButtonElement;
}

/** Builds the dialog (closed) in `document.body`. */
export function makeSurfaceControls(): SurfaceControls {
  const coordinate = (name: string) => make('input', { type: 'number', step: 'any', inputMode: 'decimal', testid: `surface-${name}` });
  const c: SurfaceControls = {
    dialog: make('dialog', { className: 'surface-dialog', testid: 'surface-dialog' }),
    title: make('h2', { id: 'surface-title', textContent: 'Surface' }),
    letter: make('select', { testid: 'surface-letter' }),
    canvas: make('canvas', { className: 'surface-view', testid: 'surface-view', tabIndex: 0 }),
    status: make('p', { className: 'text-panel-status', testid: 'surface-status', role: 'status' }),
    library: make('div', { className: 'surface-library', hidden: true }),
    writeOut: make('button', { type: 'button', testid: 'surface-write-out', textContent: 'Write its patches into the grammar' }),
    point: make('select', { testid: 'surface-point' }),
    coordinates: [coordinate('x'), coordinate('y'), coordinate('z')],
    axis: make('select', { testid: 'surface-axis' }),
    frame: make('button', { type: 'button', className: 'quiet', textContent: 'Frame', testid: 'surface-frame' }),
    close: make('button', { type: 'button', className: 'quiet', textContent: 'Close', testid: 'surface-close' }),
  };
  c.dialog.setAttribute('aria-labelledby', c.title.id);
  c.letter.setAttribute('aria-label', 'Surface');
  c.canvas.setAttribute('role', 'application');
  c.canvas.setAttribute('aria-label', 'Surface view: drag a control point; arrow keys move the chosen point (Page Up and Page Down along z, Shift ten times as far), [ and ] choose the point before or after');
  c.canvas.setAttribute('aria-describedby', c.status.id = 'surface-status');
  for (const [value, label] of [
    ['', 'facing the camera'],
    ['0', 'along x'],
    ['1', 'along y'],
    ['2', 'along z'],
  ]) {
    c.axis.append(make('option', { value, textContent: label }));
  }
  c.library.append(make('p', { className: 'hint', textContent: 'A shape of the library: its control points are not in the text. Write them out as patch lines to edit them (one undo step).' }), c.writeOut);
  const field = (label: string, control: HTMLElement) => make('label', { className: 'field' }, `${label} `, control);
  c.dialog.append(
    make('header', { className: 'dialog-header' }, c.title, c.letter, c.close),
    make(
      'div',
      { className: 'surface-body' },
      c.canvas,
      make(
        'div',
        { className: 'surface-side' },
        c.status,
        c.library,
        field('Point', c.point),
        make('div', { className: 'text-panel-row' }, field('x', c.coordinates[0]), field('y', c.coordinates[1]), field('z', c.coordinates[2])),
        field('Drag', c.axis),
        make('p', { className: 'hint', textContent: 'Drag a point: the text follows (Ctrl+Z there undoes a drag). Drag elsewhere to turn the view.' }),
        c.frame,
      ),
    ),
  );
  document.body.append(c.dialog);
  return c;
}
