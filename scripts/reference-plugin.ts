// A vite plugin that renders the language reference (docs/LANGUAGE.md) to an HTML fragment with
// marked, serves it in dev and emits it as an asset of the build (web/src/editor/reference.ts says
// where), so the site ships HTML and no Markdown library. The Help panel loads it when it first
// opens. What the rendering adds to plain Markdown:
// - every heading gets GitHub's id (the README's links into LANGUAGE.md work in the panel too), and
//   the fragment starts with a table of contents of the sections;
// - in a table whose first column is `command` or `directive`, each name written in code in a row's
//   first cell gets the id `referenceAnchor(name)` (the first row that names it), which hover docs
//   link to;
// - links to files of the repository (not part of the site) become their text; raw HTML is
//   escaped, so the doc's text is only ever text.
import { readFileSync } from 'node:fs';
import { Marked, type RendererThis, type Tokens } from 'marked';
import type { Plugin } from 'vite';
import { REFERENCE_PATH, referenceAnchor } from '../web/src/editor/reference.ts';

/** The first header of a table whose rows name modules or directives. */
const NAMING_TABLES = new Set(['command', 'directive']);

function escapeHtml(text: string): string {
  return text.replace(/[&<>"']/g, (c) => `&#${c.charCodeAt(0)};`);
}

/** GitHub's id of a heading: lower case, punctuation dropped, spaces as hyphens. */
export function headingSlug(text: string): string {
  return text
    .toLowerCase()
    .replace(/[^\p{L}\p{N}\s_-]/gu, '')
    .trim()
    .replace(/\s/g, '-');
}

interface Section {
  id: string;
  text: string;
  depth: number;
}

/** The table of contents: the sections (##) with their subsections (###). */
function contents(sections: readonly Section[]): string {
  let html = '';
  let open = false;
  for (const { id, text, depth } of sections) {
    const item = `<li><a href="#${escapeHtml(id)}">${escapeHtml(text)}</a>`;
    if (depth === 2) {
      html += `${open ? '</ol></li>' : ''}${item}<ol>`;
      open = true;
    } else html += `${item}</li>`;
  }
  if (open) html += '</ol></li>';
  return `<nav class="reference-toc" aria-label="Contents"><details><summary>Contents</summary><ol>${html.replaceAll('<ol></ol>', '')}</ol></details></nav>`;
}

/** docs/LANGUAGE.md as the Help panel's HTML: contents, then the document. */
export function renderReference(markdown: string): string {
  const ids = new Set<string>();
  const sections: Section[] = [];
  const unique = (id: string) => {
    let candidate = id;
    for (let n = 1; ids.has(candidate); n++) candidate = `${id}-${n}`;
    ids.add(candidate);
    return candidate;
  };

  /** A table cell's inline HTML; in the first cell of a naming table, each name in code carries its anchor. */
  function cell(this: RendererThis, token: Tokens.TableCell, named: boolean): string {
    if (!named) return this.parser.parseInline(token.tokens);
    return token.tokens
      .map((t) => {
        if (t.type !== 'codespan') return this.parser.parseInline([t]);
        return (t as Tokens.Codespan).text
          .split(/\s+/)
          .map((name) => {
            const anchor = referenceAnchor(name);
            const id = ids.has(anchor) ? '' : ` id="${escapeHtml(unique(anchor))}"`;
            return `<code${id}>${escapeHtml(name)}</code>`;
          })
          .join(' ');
      })
      .join('');
  }

  const marked = new Marked({
    gfm: true,
    renderer: {
      heading({ tokens, depth }) {
        const text = this.parser.parseInline(tokens, this.parser.textRenderer);
        const id = unique(headingSlug(text));
        if (depth === 2 || depth === 3) sections.push({ id, text, depth });
        // One level down: the panel's own title is the page's heading.
        const level = Math.min(depth + 1, 6);
        return `<h${level} id="${escapeHtml(id)}">${this.parser.parseInline(tokens)}</h${level}>\n`;
      },
      table(token) {
        const naming = NAMING_TABLES.has(token.header[0]?.text.trim().toLowerCase() ?? '');
        const align = (i: number) => (token.align[i] ? ` style="text-align: ${token.align[i]}"` : '');
        const head = token.header.map((h, i) => `<th${align(i)}>${this.parser.parseInline(h.tokens)}</th>`).join('');
        const rows = token.rows.map((row) => {
          const cells = row.map((c, i) => `<td${align(i)}>${cell.call(this, c, naming && i === 0)}</td>`).join('');
          return `<tr>${cells}</tr>\n`;
        });
        return `<table>\n<thead><tr>${head}</tr></thead>\n<tbody>\n${rows.join('')}</tbody>\n</table>\n`;
      },
      link({ href, tokens }) {
        const text = this.parser.parseInline(tokens);
        if (href.startsWith('#')) return `<a href="${escapeHtml(href)}">${text}</a>`;
        if (/^https?:\/\//.test(href)) return `<a href="${escapeHtml(href)}" target="_blank" rel="noopener noreferrer">${text}</a>`;
        return text; // a file of the repository: not on the site
      },
      image({ text }) {
        return escapeHtml(text);
      },
      html({ text }) {
        return escapeHtml(text);
      },
    },
  });
  const body = marked.parse(markdown, { async: false });
  return `${contents(sections)}\n<article class="reference-body">\n${body}</article>\n`;
}

/** The plugin; `markdownFile` is docs/LANGUAGE.md. */
export function referencePlugin(markdownFile: string): Plugin {
  const html = () => renderReference(readFileSync(markdownFile, 'utf8'));
  return {
    name: 'meristem-language-reference',
    configureServer(server) {
      // Rendered on every request, so an edit of the doc shows at the next opening of the panel.
      server.middlewares.use((request, response, next) => {
        const path = (request.url ?? '').split('?')[0];
        if (!path.endsWith(`/${REFERENCE_PATH}`)) return next();
        response.setHeader('Content-Type', 'text/html; charset=utf-8');
        response.end(html());
      });
    },
    generateBundle() {
      this.emitFile({ type: 'asset', fileName: REFERENCE_PATH, source: html() });
    },
  };
}
