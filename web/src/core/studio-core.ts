// The studio core: the whole boundary's module (crate/pkg) put to use for inspecting builds, so
// their inspectors explain productions, report matches and trace the derivation (feature
// `studio-extras`, which the first plant's core leaves out: issue 22). The build worker loads this
// file on the first such question (`loadStudioCore`); unit tests import it after `initIo`.
import { build as studioBuild, buildOn as studioBuildOn } from '../../../crate/pkg/meristem.js';
import { useStudioCore } from './build';
import { environmentOf } from './environment';
import { initIo } from './io';
import { SpareCopies } from './spare-copies';

/**
 * Instantiates crate/pkg (once, see `initIo`) and makes `inspectPlant` build with it, copying big
 * plants for the GPU into spare buffers (`prepareSpares`) and continuing a kept build's derivation
 * when asked (`buildOn`), and copying each build's environment for the views.
 */
export async function startStudioCore(): Promise<void> {
  await initIo();
  useStudioCore(studioBuild, new SpareCopies(), studioBuildOn, environmentOf);
}
