// Share links: the whole state in the link's fragment; the text the studio opens with (a link's,
// the autosaved one, the first example), the Share button and dialog, embed snippets, pasted links.
// share-dialog and embed-snippets are not re-exported: they load with the first share.
export { startingText, type StartingText } from './link-opening';
export { wireLinks } from './wire-links';
