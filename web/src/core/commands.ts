// The core's turtle command table, the one source for highlighting and hover docs.
import { commands } from '../../../crate/pkg/meristem.js';
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
