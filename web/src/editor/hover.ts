// Hover docs: pointing at a turtle command shows its line from the core's command table.
import { syntaxTree } from '@codemirror/language';
import type { Extension } from '@codemirror/state';
import { hoverTooltip } from '@codemirror/view';
import type { GrammarDirective, TurtleCommand } from '../core';

/** Text of the hover for a command, e.g. `F — Move forward by the step length and draw a segment.` */
export function commandHoverText(command: TurtleCommand): string {
  const params = command.params.length > 0 ? `(${command.params.join(', ')})` : '';
  return `${command.name}${params} — ${command.doc}`;
}

/** Text of the hover for a directive, e.g. `#tropism x y z e — The tropism vector…`. */
export function directiveHoverText(directive: GrammarDirective): string {
  return `#${directive.name} ${directive.args} — ${directive.doc}`;
}

/** Syntax node names (token names of the grammar language) that stand for a turtle command. */
const COMMAND_NODES = new Set(['turtleCommand', 'squareBracket']);

/**
 * The token class of a syntax node: the grammar language names a token that also carries the
 * part of a production it is in `turtleCommand_predecessor`; the class is the first word.
 */
export function tokenClass(nodeName: string): string {
  return nodeName.split('_')[0];
}

/** A tooltip with the doc of the turtle command or directive under the pointer (not in comments, arrows, …). */
export function commandHover(commands: readonly TurtleCommand[], directives: readonly GrammarDirective[] = []): Extension {
  const byName = new Map(commands.map((c) => [c.name, c]));
  const directiveByName = new Map(directives.map((d) => [`#${d.name}`, d]));
  return hoverTooltip((view, pos, side) => {
    const node = syntaxTree(view.state).resolveInner(pos, side);
    const kind = tokenClass(node.name);
    const word = view.state.sliceDoc(node.from, node.to);
    const directive = kind === 'directive' ? directiveByName.get(word) : undefined;
    const command = COMMAND_NODES.has(kind) ? byName.get(word) : undefined;
    const text = directive ? directiveHoverText(directive) : command ? commandHoverText(command) : null;
    if (text === null) return null;
    return {
      pos: node.from,
      end: node.to,
      above: true,
      create: () => {
        const dom = document.createElement('div');
        dom.className = 'cm-command-doc';
        dom.textContent = text;
        return { dom };
      },
    };
  });
}
