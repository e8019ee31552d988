// Code blocks (the reference's, the lessons') scroll sideways when their lines are longer than the
// panel: each is a tab stop, so a keyboard alone can scroll it (WCAG 2.1.1; axe's
// scrollable-region-focusable).

/** Makes every `<pre>` under `root` focusable. */
export function focusableCode(root: ParentNode): void {
  for (const pre of root.querySelectorAll('pre')) pre.tabIndex = 0;
}
