// Offline use and "a new version is ready" (app-update.ts) load after the first plant: the first
// load carries neither their code nor the service worker's registration (issue 22).

/** Loads app-update.ts and vite-plugin-pwa's `registerSW`, then registers the service worker. */
export function loadAppUpdates(): Promise<void> {
  return Promise.all([import('./app-update'), import('virtual:pwa-register')])
    .then(([{ installAppUpdates }, { registerSW }]) => installAppUpdates(registerSW))
    .catch((error: unknown) => console.error('Could not set up offline use:', error));
}
