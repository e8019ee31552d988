// The example the studio opens with when there is no text to restore (public/examples); the built
// index.html preloads it (vite.config.ts), so it downloads with the script (issue 22).

/** The file of public/examples shown at start. */
export const INITIAL_EXAMPLE = 'abop-1.24d.lsys';
