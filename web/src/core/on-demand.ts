// What loads on first use (issue 22: the first load carries none of it): a module of the core, a
// dialog, a panel. One rule for all: made once and kept, and a failure (the network) is tried
// again on the next use.

/** `make`, called on the first use and kept (a failure is tried again on the next use). */
export function onDemand<T>(make: () => Promise<T>): () => Promise<T> {
  let made: Promise<T> | undefined;
  return () =>
    (made ??= make().catch((error: unknown) => {
      made = undefined;
      throw error;
    }));
}
