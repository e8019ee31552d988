// Loads the studio core on demand (./studio-core.ts, and crate/pkg with it): what answers the
// inspector's explanations, match reports and traced derivation, which the first plant's core
// leaves out (issue 22, the first load).
let loading: Promise<void> | undefined;

/**
 * Loads the studio core once; later calls return the same promise. After it, `inspectPlant`
 * builds with it and its inspectors answer every question. A failed load (the network) is tried
 * again by the next call.
 */
export function loadStudioCore(): Promise<void> {
  loading ??= import('./studio-core')
    .then((studio) => studio.startStudioCore())
    .catch((error: unknown) => {
      loading = undefined;
      throw error;
    });
  return loading;
}
