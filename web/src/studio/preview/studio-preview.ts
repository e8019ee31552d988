// The studio's live preview, wired to its parts: the text and the options it builds with, where
// it says how the build went, and who takes over each build on screen (the inspector).
import type { BuildClient } from '../../build';
import type { LazyGrammarEditor } from '../../editor/grammar-text';
import type { PlantView } from '../../view';
import { tubesFor, type ViewOptions } from '../controls';
import type { DerivationControls, Inspector } from '../derivation';
import type { Notice, StudioElements } from '../page';
import type { LazyTimeline } from '../timeline';
import { reportCoreCrashes } from './core-crashes';
import type { DiagnosticsFeed } from './diagnostics-feed';
import { LivePreview } from './live-preview';

/** What the studio's preview reads. */
export interface StudioPreviewParts extends Inspector {
  els: StudioElements;
  client: BuildClient;
  feed: DiagnosticsFeed;
  view: PlantView;
  editor: LazyGrammarEditor;
  derivation: DerivationControls;
  viewOptions: ViewOptions;
  notice: Notice;
  timeline: LazyTimeline;
}

/** The live preview of the editor's text, with the derivation's and the view's options. */
export function createLivePreview(parts: StudioPreviewParts): LivePreview {
  const { els, editor, contexts, derivationView, derivation, viewOptions } = parts;
  return new LivePreview({
    client: parts.client,
    feed: parts.feed,
    view: parts.view,
    status: els.status,
    stop: els.stopBuild,
    problems: els.showProblems,
    staleBadge: els.staleBadge,
    inspectorStale: els.inspectorStale,
    workerReplaced: () => {
      contexts.reload();
      derivationView.reload();
    },
    text: () => editor.text(),
    options: () => {
      // (A stepwise grammar's steps at t replace the iterations.)
      const timeline = parts.timeline.buildOptions();
      return {
        iterations: derivation.iterations(),
        seed: derivation.seed(),
        sides: viewOptions.values.sides,
        smoothAll: viewOptions.values.smoothAll,
        // The Lines mode (and `auto` for a flat plant) draws no tubes: they are not meshed (its lines
        // grow by the segments' growth times, which the growth arrays carry).
        tubes: tubesFor(viewOptions.values.render),
        ...timeline,
      };
    },
    blamed: (diagnostics) => derivation.ofText(diagnostics),
    diagnosticsChanged: () => editor.refreshDiagnostics(),
    // The panels follow the plant on screen (while the growth plays, at the timeline's pace).
    adopt: (result) =>
      parts.timeline.handOver({
        give: () => {
          contexts.setBuild(result.build, result.inspector, result.source, result.options);
          derivationView.setBuild(result.build, result.inspector);
          contexts.cursorAt(editor.cursor());
        },
        drop: () => result.inspector.free(),
      }),
    crashed: reportCoreCrashes(parts.notice),
  });
}
