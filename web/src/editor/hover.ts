// Hover docs: pointing at a turtle command shows its line from the core's command table.
import { syntaxTree } from '@codemirror/language';
import type { Extension } from '@codemirror/state';
import { hoverTooltip } from '@codemirror/view';
import type { TurtleCommand } from '../core';

/** Text of the hover for a command, e.g. `F — Move forward by the step length and draw a segment.` */
export function commandHoverText(command: TurtleCommand): string {
  const params = command.params.length > 0 ? `(${command.params.join(', ')})` : '';
  return `${command.name}${params} — ${command.doc}`;
}

/** Syntax node names (token names of the grammar language) that stand for a turtle command. */
const COMMAND_NODES = new Set(['turtleCommand', 'squareBracket']);

/** A tooltip with the doc of the turtle command under the pointer (not in comments, arrows, …). */
export function commandHover(commands: readonly TurtleCommand[]): Extension {
  const byName = new Map(commands.map((c) => [c.name, c]));
  return hoverTooltip((view, pos, side) => {
    const node = syntaxTree(view.state).resolveInner(pos, side);
    if (!COMMAND_NODES.has(node.name)) return null;
    const command = byName.get(view.state.sliceDoc(node.from, node.to));
    if (!command) return null;
    return {
      pos: node.from,
      end: node.to,
      above: true,
      create: () => {
        const dom = document.createElement('div');
        dom.className = 'cm-command-doc';
        dom.textContent = commandHoverText(command);
        return { dom };
      },
    };
  });
}
