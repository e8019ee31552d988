// Hover docs: pointing at a module with a meaning or a directive shows its row of the core's
// vocabulary, with a link to its row of the language reference (the studio's Help panel).
import { syntaxTree } from '@codemirror/language';
import type { Extension } from '@codemirror/state';
import { closeHoverTooltips, hoverTooltip } from '@codemirror/view';
import { writtenDirective, type Vocabulary } from '../core';
import { commandHoverText, directiveHoverText } from './hover-text';
import { referenceAnchor } from './reference';

export { commandHoverText, directiveHoverText };

/** Syntax node names (token names of the grammar language) that stand for a turtle command. */
const COMMAND_NODES = new Set(['turtleCommand', 'squareBracket']);

/**
 * The token class of a syntax node: the grammar language names a token that also carries the
 * part of a production it is in `turtleCommand_predecessor`; the class is the first word.
 */
export function tokenClass(nodeName: string): string {
  return nodeName.split('_')[0];
}

/**
 * A tooltip with the doc of the turtle command or directive under the pointer (not in comments,
 * arrows, …); with `openReference`, a "Reference" link calls it with the anchor of the name's row.
 */
export function commandHover(vocabulary: Vocabulary, openReference?: (anchor: string) => void): Extension {
  const byName = new Map(vocabulary.modules.map((c) => [c.name, c]));
  const directiveByName = new Map(vocabulary.directives.map((d) => [writtenDirective(d), d]));
  return hoverTooltip((view, pos, side) => {
    const node = syntaxTree(view.state).resolveInner(pos, side);
    const kind = tokenClass(node.name);
    const word = view.state.sliceDoc(node.from, node.to);
    const directive = kind === 'directive' ? directiveByName.get(word) : undefined;
    const command = COMMAND_NODES.has(kind) ? byName.get(word) : undefined;
    const text = directive ? directiveHoverText(directive) : command ? commandHoverText(command) : null;
    if (text === null) return null;
    const anchor = referenceAnchor(directive ? writtenDirective(directive) : word);
    return {
      pos: node.from,
      end: node.to,
      above: true,
      create: (view) => {
        const dom = document.createElement('div');
        dom.className = 'cm-command-doc';
        dom.textContent = text;
        if (openReference) {
          const link = Object.assign(document.createElement('button'), { type: 'button', className: 'cm-reference-link', textContent: 'Reference' });
          link.title = 'Open this row of the language reference (Help)';
          link.dataset.testid = 'hover-reference';
          link.addEventListener('click', () => {
            view.focus(); // where the focus returns when the reference closes
            view.dispatch({ effects: closeHoverTooltips });
            openReference(anchor);
          });
          dom.append(' ', link);
        }
        return { dom };
      },
    };
  });
}
