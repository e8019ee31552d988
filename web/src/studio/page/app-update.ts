// Offline use and updates (issue 22): the service worker the build generates (vite-plugin-pwa,
// workbox: see vite.config.ts) is registered by the studio page. Once installed it serves the whole
// site, so the studio starts with the network off. A newer deployment installs beside it and waits:
// a bar says "A new version is ready — reload", and Reload switches to it and reloads the page
// (work in progress is autosaved, and restored on reload). Later keeps the running version.
import './app-update.css';

/** What vite-plugin-pwa's `registerSW` (virtual:pwa-register) takes and gives, as far as used here. */
export type RegisterServiceWorker = (options: {
  onNeedRefresh?: () => void;
  onRegisterError?: (error: unknown) => void;
}) => (reloadPage?: boolean) => Promise<void>;

/** Registers the service worker; shows the update bar in `parent` when a new version waits. */
export function installAppUpdates(register: RegisterServiceWorker, parent: HTMLElement = document.body): void {
  if (!('serviceWorker' in navigator)) return;
  let bar: HTMLElement | undefined;
  const update = register({
    onNeedRefresh: () => {
      bar ??= updateBar(parent, () => void update(true), () => bar?.remove());
      if (!bar.isConnected) parent.append(bar);
    },
    // Without a service worker the studio works as before, online; nothing to tell the user.
    onRegisterError: (error) => console.warn('Meristem: no offline use (the service worker did not register):', error),
  });
}

/** The bar: its text, Reload and Later. */
function updateBar(parent: HTMLElement, reload: () => void, later: () => void): HTMLElement {
  const bar = document.createElement('div');
  bar.className = 'update-ready';
  bar.dataset.testid = 'update-ready';
  bar.setAttribute('role', 'status');
  const text = document.createElement('span');
  text.textContent = 'A new version is ready — reload to use it.';
  const reloadButton = document.createElement('button');
  reloadButton.type = 'button';
  reloadButton.className = 'primary';
  reloadButton.dataset.testid = 'update-reload';
  reloadButton.textContent = 'Reload';
  reloadButton.addEventListener('click', () => {
    reloadButton.disabled = true;
    reload();
  });
  const laterButton = document.createElement('button');
  laterButton.type = 'button';
  laterButton.className = 'quiet';
  laterButton.dataset.testid = 'update-later';
  laterButton.textContent = 'Later';
  laterButton.addEventListener('click', later);
  bar.append(text, reloadButton, laterButton);
  parent.append(bar);
  return bar;
}
