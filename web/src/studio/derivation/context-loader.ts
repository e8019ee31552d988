// The String tab's context view, loaded after the first plant (issue 22: the first plant needs none
// of it). Until it has loaded it keeps the last build and cursor, and hands them over on arrival.
import type { BuildOptions, PlantBuild, PlantInspector } from '../../core';
import type { GrammarEditor } from '../../editor';
import type { PlantView } from '../../view';
import type { ViewOptions } from '../controls';
import type { ContextView, ContextViewElements } from './context-view';

/** A {@link ContextView} made when {@link LazyContextView.load} is first called. */
export class LazyContextView {
  private view: ContextView | undefined;
  private loading: Promise<void> | undefined;
  private build: [PlantBuild, PlantInspector | undefined, string, BuildOptions?] | undefined;
  private cursor: number | undefined;
  private pickingOn = true;

  constructor(
    private readonly els: ContextViewElements,
    private readonly plantView: PlantView,
    private readonly editor: () => GrammarEditor | undefined,
    private readonly viewOptions: ViewOptions,
  ) {}

  /** Loads and makes the view (once; a failure is logged, and the next call tries again). */
  load(): Promise<void> {
    return (this.loading ??= this.make());
  }

  private async make(): Promise<void> {
    try {
      const { ContextView } = await import('./context-view');
      const view = new ContextView(this.els, this.plantView, this.editor, this.viewOptions);
      view.picking = this.pickingOn;
      if (this.build) view.setBuild(...this.build);
      if (this.cursor !== undefined) view.cursorAt(this.cursor);
      this.view = view;
    } catch (error) {
      this.loading = undefined;
      console.error('The String tab could not load:', error);
    }
  }

  /** As {@link ContextView.setBuild}, which owns `inspector`: kept (and the one it replaces freed) until the view has loaded. */
  setBuild(build: PlantBuild, inspector: PlantInspector | undefined, source: string, options?: BuildOptions): void {
    if (this.view) return this.view.setBuild(build, inspector, source, options);
    const old = this.build?.[1];
    if (old !== inspector) old?.free();
    this.build = [build, inspector, source, options];
  }

  /** As {@link ContextView.cursorAt}. */
  cursorAt(pos: number): void {
    this.cursor = pos;
    this.view?.cursorAt(pos);
  }

  /** As {@link ContextView.pickModule}: nothing is picked before the view has loaded. */
  pickModule(module: number | null): void {
    this.view?.pickModule(module);
  }

  /** As {@link ContextView.showPreview}. */
  showPreview(modules: Iterable<number> | null, production: number | null): void {
    this.view?.showPreview(modules, production);
  }

  /** As {@link ContextView.describeProduction} (`rule 3` before the view has loaded). */
  describeProduction(index: number): string {
    return this.view?.describeProduction(index) ?? `rule ${index + 1}`;
  }

  /** As {@link ContextView.conditionOf}. */
  conditionOf(index: number): string | null {
    return this.view?.conditionOf(index) ?? null;
  }

  /** As {@link ContextView.reload}. */
  reload(): void {
    this.view?.reload();
  }

  /** As {@link ContextView.picking}: clicks on the plant pick modules. */
  get picking(): boolean {
    return this.pickingOn;
  }

  set picking(on: boolean) {
    this.pickingOn = on;
    if (this.view) this.view.picking = on;
  }
}
