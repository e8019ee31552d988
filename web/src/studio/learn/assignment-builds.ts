// The assignment's builds: each grammar built as written (its own #iterations and #seed, tubes
// drawn), one at a time, in a build worker of its own (the live preview's is the plant on screen's),
// for the file's validation, a student's Check and a submission's verdicts alike.
import { BuildClient, createBuildWorker } from '../../build';
import { directiveOfKind, loadVocabulary, writtenDirective } from '../../core';
import type { Built, GrammarBuilder } from './assignment-validate.ts';
import { writtenSeed } from './written-seed';

/** A builder over a build worker of its own, started on the first build; `dispose` stops it. */
export function workerBuilder(): { builder: GrammarBuilder; dispose(): void } {
  let client: BuildClient | undefined;
  let queue: Promise<unknown> = Promise.resolve();
  const buildOne = async (text: string): Promise<Built> => {
    if (!client) {
      client = new BuildClient(createBuildWorker);
      client.useStudioCore(); // timed grammars, surfaces and environments build as in the studio
    }
    const outcome = await client.request(text, { tubes: true });
    if (outcome.kind !== 'built') return { ok: false, reason: outcome.kind === 'crashed' ? `the core stopped on it (${outcome.message})` : 'the build was stopped' };
    const seedDirective = writtenDirective(directiveOfKind(await loadVocabulary(), 'Seed'));
    const { build, inspector } = outcome.result;
    return { ok: true, build, inspector, textSeed: writtenSeed(text, seedDirective) };
  };
  const builder: GrammarBuilder = (text) => {
    const next = queue.then(() => buildOne(text));
    queue = next.catch(() => undefined);
    return next;
  };
  return {
    builder,
    dispose: () => {
      client?.dispose();
      client = undefined;
    },
  };
}
