// Building plants off the page's thread, used by the studio and by embeds: the build worker
// (`worker.ts`, the core in a worker), its client (`worker-client.ts`: one build at a time, the
// newest wins, a stopped or crashed worker replaced), their messages (`worker-protocol.ts`), the
// worker started early by the boot script (`build-worker-start.ts`), and `worker-job.ts`, one job
// in a worker of its own (the studio's imports and exports).
export { BuildClient, createBuildWorker, type BuildOutcome, type BuildResult, type WorkerLike } from './worker-client';
export { runWorkerJob, type JobWorkerLike, type WorkerJob } from './worker-job';
