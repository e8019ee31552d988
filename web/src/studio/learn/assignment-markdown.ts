// An assignment's Markdown as the lessons show it (GitHub's dialect, headings two levels down), but
// from a file the studio does not own: HTML written in it is shown as text, never run; the result
// is parsed in an inert document and only an allowlist of elements and attributes is copied into
// the page (links to http, https and mailto only, opened in a new tab; images over http and https).
// Relative links and images are relative to the assignment's file. Loaded with the assignment panel.
import { Marked, type Token } from 'marked';

/** Text as HTML text. */
function escapeHtml(text: string): string {
  return text.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');
}

/** The elements copied from the rendered Markdown; anything else is replaced by its text. */
const ELEMENTS = new Set([
  'P', 'H3', 'H4', 'H5', 'H6', 'EM', 'STRONG', 'DEL', 'CODE', 'PRE', 'UL', 'OL', 'LI', 'A', 'IMG', 'BLOCKQUOTE', 'HR', 'BR',
  'TABLE', 'THEAD', 'TBODY', 'TR', 'TH', 'TD', 'INPUT',
]);

/** A URL of a link or image, resolved against the file, if its scheme is allowed. */
function safeUrl(value: string | null, base: string, schemes: string[]): string | null {
  if (value === null) return null;
  try {
    const url = new URL(value, base);
    return schemes.includes(url.protocol) ? url.href : null;
  } catch {
    return null;
  }
}

/** Copies `from`'s children into `into`, keeping only allowed elements and attributes. */
function copyAllowed(from: Node, into: Node, base: string): void {
  for (const child of from.childNodes) {
    if (child.nodeType === Node.TEXT_NODE) {
      into.appendChild(document.createTextNode(child.textContent ?? ''));
      continue;
    }
    if (!(child instanceof Element)) continue;
    if (!ELEMENTS.has(child.tagName)) {
      into.appendChild(document.createTextNode(child.textContent ?? ''));
      continue;
    }
    const copy = document.createElement(child.tagName.toLowerCase());
    if (child.tagName === 'A') {
      const href = safeUrl(child.getAttribute('href'), base, ['http:', 'https:', 'mailto:']);
      if (href) {
        copy.setAttribute('href', href);
        copy.setAttribute('target', '_blank');
        copy.setAttribute('rel', 'noopener noreferrer');
      }
    } else if (child.tagName === 'IMG') {
      const src = safeUrl(child.getAttribute('src'), base, ['http:', 'https:']);
      if (src) copy.setAttribute('src', src);
      copy.setAttribute('alt', child.getAttribute('alt') ?? '');
      copy.setAttribute('referrerpolicy', 'no-referrer');
    } else if (child.tagName === 'INPUT') {
      if (child.getAttribute('type') !== 'checkbox') continue;
      copy.setAttribute('type', 'checkbox');
      copy.setAttribute('disabled', '');
      if (child.hasAttribute('checked')) copy.setAttribute('checked', '');
    } else if ((child.tagName === 'TH' || child.tagName === 'TD') && /^(left|right|center)$/.test(child.getAttribute('align') ?? '')) {
      copy.setAttribute('align', child.getAttribute('align')!);
    }
    copyAllowed(child, copy, base);
    into.appendChild(copy);
  }
}

const markdown = new Marked({
  gfm: true,
  async: false,
  walkTokens: (token: Token) => {
    if (token.type === 'heading') token.depth = Math.min(6, token.depth + 2);
  },
  renderer: { html: ({ text }) => escapeHtml(text) },
});

/** The Markdown as page elements (a fragment), links and images relative to `base` (the file's URL). */
export function renderMarkdown(text: string, base: string): DocumentFragment {
  const html = markdown.parse(text, { async: false });
  const inert = new DOMParser().parseFromString(`<!doctype html><body>${html}`, 'text/html');
  const fragment = document.createDocumentFragment();
  copyAllowed(inert.body, fragment, base);
  return fragment;
}
