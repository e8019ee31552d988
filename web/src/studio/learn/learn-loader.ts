// The Learn panel is loaded on the first click of its button (a dynamic import): its code and the
// lessons' checks are not part of the first load of the studio (issue 22's budget).
import type { LearnHost } from './learn-panel';
import { byId } from '../page';

/** Makes the Learn button load the panel, then open it; the panel takes the button over. */
export function installLearnPanel(host: LearnHost): void {
  const toggle = byId('open-learn', HTMLButtonElement);
  const panel = byId('learn', HTMLElement);
  const first = () => {
    toggle.removeEventListener('click', first);
    // Open at once, as the panel itself does; its contents follow when its code has loaded.
    panel.hidden = false;
    toggle.setAttribute('aria-expanded', 'true');
    toggle.setAttribute('aria-busy', 'true');
    panelCode()
      .then(({ LearnPanel, learnElements }) => new LearnPanel(learnElements(), host).open())
      .catch((error: unknown) => {
        console.error('Could not load the lessons:', error);
        panel.hidden = true;
        toggle.setAttribute('aria-expanded', 'false');
        toggle.addEventListener('click', first); // try again on the next click
      })
      .finally(() => toggle.removeAttribute('aria-busy'));
  };
  toggle.addEventListener('click', first);
  // An assignment or a submission in the address (docs/ASSIGNMENTS.md), or pasted into it later.
  const assignment = () => void panelCode().then((code) => code.openFromAddress(host));
  if (/(assignment|submission)=/.test(location.href)) assignment();
  addEventListener('hashchange', () => {
    if (/^#(assignment|submission)=/.test(location.hash)) assignment();
  });
}

/** The panel's code (one import, so the first load holds its address once). */
const panelCode = () => import('./learn-panel');
