// The core's turtle command and directive tables, the one source for highlighting, completion and
// hover docs.
import { commands, directives } from '../../../crate/pkg/meristem.js';
import { assertReady } from './init';

/** One turtle command as the core's table (`crate/src/turtle/commands.rs`) declares it. */
export interface TurtleCommand {
  /** The module name that invokes it, e.g. `F` or `+`. */
  name: string;
  /** Names of its parameters (empty for the non-parametric commands). */
  params: string[];
  /** One sentence for hover docs and the reference. */
  doc: string;
  /** Kind of command: `move`, `rotate`, `branch`, … */
  category: string;
}

/** The turtle commands the core interprets, in table order. Requires {@link initCore}. */
export function turtleCommands(): TurtleCommand[] {
  assertReady();
  return JSON.parse(commands()) as TurtleCommand[];
}

/** One directive as the core's table (`crate/src/model/directives.rs`) declares it. */
export interface GrammarDirective {
  /** The name without `#`, e.g. `angle`. */
  name: string;
  /** How its arguments are written, e.g. `x y z e`. */
  args: string;
  /** One sentence for completion and the reference. */
  doc: string;
}

/** The directives the core accepts, in table order. Requires {@link initCore}. */
export function grammarDirectives(): GrammarDirective[] {
  assertReady();
  return JSON.parse(directives()) as GrammarDirective[];
}
