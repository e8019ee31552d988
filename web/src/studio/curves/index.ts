// The curve editor (issue 48): a `#curve` or `#table` function's points dragged in a small plot,
// the grammar's line following; wired with the surface editor, loaded on its first opening.
export { wireCurveEditing } from './wire-curve-editing';
