// The curve editor's panel, made (closed) in the page: the plot, the chosen point's x and y, the
// buttons that add and remove a point, the value under the pointer and what the editor says of
// the curve. Made here, not in index.html: it loads with the editor's code on first use.
import { el as make } from '../page/make-element';
import { CurvePlot } from './curve-plot';
import './curve-panel.css';

/** The panel's elements. */
export interface CurveControls {
  dialog: HTMLDialogElement;
  title: HTMLElement;
  plot: CurvePlot;
  status: HTMLElement;
  under: HTMLElement;
  coordinates: [HTMLInputElement, HTMLInputElement];
  add: HTMLButtonElement;
  remove: HTMLButtonElement;
  fit: HTMLButtonElement;
  close: HTMLButtonElement;
}

/** Builds the panel (closed) in `document.body`. */
export function makeCurveControls(): CurveControls {
  const coordinate = (name: string) => make('input', { type: 'number', step: 'any', inputMode: 'decimal', testid: `curve-${name}` });
  const c: CurveControls = {
    dialog: make('dialog', { className: 'curve-dialog', testid: 'curve-dialog' }),
    title: make('h2', { id: 'curve-title', textContent: 'Curve' }),
    plot: new CurvePlot(),
    status: make('p', { className: 'text-panel-status', testid: 'curve-status', role: 'status', id: 'curve-status' }),
    under: make('p', { className: 'curve-under-text', testid: 'curve-under' }),
    coordinates: [coordinate('x'), coordinate('y')],
    add: make('button', { type: 'button', testid: 'curve-add', textContent: '+ Point' }),
    remove: make('button', { type: 'button', testid: 'curve-remove', textContent: '− Point' }),
    fit: make('button', { type: 'button', className: 'quiet', testid: 'curve-fit', textContent: 'Fit' }),
    close: make('button', { type: 'button', className: 'quiet', testid: 'curve-close', textContent: 'Close' }),
  };
  const plot = c.plot.element;
  plot.dataset.testid = 'curve-plot';
  plot.setAttribute('tabindex', '0');
  plot.setAttribute('role', 'application');
  plot.setAttribute(
    'aria-label',
    'Curve: drag a point, double-click to add one. Arrow keys move the chosen point (Shift ten times as far, Alt a tenth), [ and ] choose the point before or after, Home and End the first and the last, Insert adds a point, Delete removes the chosen one',
  );
  plot.setAttribute('aria-describedby', c.status.id);
  c.dialog.setAttribute('aria-labelledby', c.title.id);
  c.add.title = 'Add a point in the widest gap, on the curve (or double-click the plot where it should go)';
  const field = (label: string, control: HTMLElement) => make('label', { className: 'field' }, `${label} `, control);
  c.dialog.append(
    make('header', { className: 'dialog-header' }, c.title, c.close),
    make(
      'div',
      { className: 'curve-body' },
      plot,
      c.under,
      make('div', { className: 'text-panel-row' }, field('x', c.coordinates[0]), field('y', c.coordinates[1]), c.add, c.remove, c.fit),
      c.status,
      make('p', { className: 'hint', textContent: 'Drag a point: the text follows (Ctrl+Z there undoes a whole drag), and the plant with it.' }),
    ),
  );
  document.body.append(c.dialog);
  return c;
}
