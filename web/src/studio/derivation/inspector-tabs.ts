// The inspector's tabs under the 3D view (String | Derivation): the WAI-ARIA tabs pattern, one
// panel shown at a time, arrow keys move between the tabs, only the selected one is in the Tab order.

/** Connects `tabs` (role=tab, each `aria-controls` its panel); `shown` hears the selected tab's id. */
export function installInspectorTabs(tabs: readonly HTMLButtonElement[], shown: (id: string) => void): void {
  const select = (tab: HTMLButtonElement, focus: boolean) => {
    for (const other of tabs) {
      const selected = other === tab;
      other.setAttribute('aria-selected', String(selected));
      other.tabIndex = selected ? 0 : -1;
      const panel = document.getElementById(other.getAttribute('aria-controls') ?? '');
      if (panel) panel.hidden = !selected;
    }
    if (focus) tab.focus();
    shown(tab.id);
  };
  tabs.forEach((tab, i) => {
    tab.addEventListener('click', () => select(tab, false));
    tab.addEventListener('keydown', (event) => {
      const step = event.key === 'ArrowRight' ? 1 : event.key === 'ArrowLeft' ? -1 : 0;
      if (step === 0) return;
      event.preventDefault();
      select(tabs[(i + step + tabs.length) % tabs.length], true);
    });
  });
}
