// The texts of the hover docs, without CodeMirror: the growth panel's titles use them before the
// editor has loaded (issue 22, the first load).
import { argumentsText, paramsText, writtenDirective, type DirectiveInfo, type ModuleInfo } from '../core';

/** Text of the hover for a module, e.g. `F(l = #step) — Move forward by l and draw a segment.` */
export function commandHoverText(module: Pick<ModuleInfo, 'name' | 'params' | 'doc'>): string {
  const params = module.params.length > 0 ? `(${paramsText(module.params)})` : '';
  return `${module.name}${params} — ${module.doc}`;
}

/** Text of the hover for a directive, e.g. `#tropism x y z e — The tropism vector…`. */
export function directiveHoverText(directive: DirectiveInfo): string {
  return `${writtenDirective(directive)} ${argumentsText(directive)} — ${directive.doc}`;
}
