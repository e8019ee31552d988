// What the studio does when the core panics (a bug): the core's own message goes to the notice bar
// and the console. A crashed build worker has already been replaced by a fresh one (the next edit
// builds again); the page's own core instance (branch editing, imports) cannot be used again, so
// the notice asks for a reload, the user's text being autosaved.
import { CoreCrashed } from '../../core';
import type { Notice } from '../page';

/**
 * Shows crashes of the page's own core (thrown from event handlers or promises) in `notice`, and
 * returns what to call when the build worker's core crashed.
 */
export function reportCoreCrashes(notice: Notice): (message: string) => void {
  const onPage = (error: unknown) => {
    if (!(error instanceof CoreCrashed)) return;
    notice.show('error', `${error.message}. Reload the page to start a fresh core; your text is saved.`);
  };
  window.addEventListener('error', (event) => onPage(event.error));
  window.addEventListener('unhandledrejection', (event) => onPage(event.reason));
  return (message) => notice.show('error', `${message}. A fresh core took over: edit the grammar to build again.`);
}
