// The inspector beside the view: the String tab (the context view) and the Derivation tab, step
// by step (loaded with its tab): its hover lights up the plant through the context view.
import type { GrammarEditor } from '../../editor/grammar-text';
import type { PlantView } from '../../view';
import type { ViewOptions } from '../controls';
import type { StudioElements } from '../page';
import { LazyContextView } from './context-loader';
import { LazyDerivationView } from './derivation-loader';
import { installInspectorTabs } from './inspector-tabs';

/** The inspector's two views of the plant on screen. */
export interface Inspector {
  /** The String tab, loaded by `contexts.load()` after the first plant. */
  contexts: LazyContextView;
  derivationView: LazyDerivationView;
}

/** The inspector on the page's elements, its Derivation tab loaded when first shown. */
export function createInspector(els: StudioElements, view: PlantView, editor: GrammarEditor, viewOptions: ViewOptions): Inspector {
  const contexts = new LazyContextView(els.contexts, view, () => editor, viewOptions);
  const derivationView = new LazyDerivationView(els.derivationPanel, {
    preview: (modules, production) => contexts.showPreview(modules, production),
    pick: (module) => contexts.pickModule(module),
    describeProduction: (index) => contexts.describeProduction(index),
    conditionOf: (index) => contexts.conditionOf(index),
  });
  installInspectorTabs(els.inspectorTabs, (tab) => derivationView.setShown(tab === 'tab-derivation'));
  return { contexts, derivationView };
}
