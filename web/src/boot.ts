// The studio page's boot script (issue 22, the first load): a small script of its own that the
// page runs as soon as it has arrived, while the studio's script (three.js, the studio) still
// downloads. It starts compiling the core as its bytes arrive and starts the build worker, which
// gets the compiled core at once; the studio (main.ts) then finds both under way (`coreModule`
// and `createBuildWorker` take them). vite.config.ts puts it in index.html's head. It imports the
// two modules it runs by file, not through their areas' indexes: the boot script stays a few KB.
import { coreModule } from './core/compile';
import { startEarlyBuildWorker } from './build/build-worker-start';

coreModule().catch(() => undefined); // a failure is the studio's to report, when it asks
startEarlyBuildWorker();
