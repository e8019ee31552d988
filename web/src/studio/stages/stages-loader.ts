// Stages (./stages.ts, with its view and its SVG), loaded when it is first turned on (issue 22: the
// first plant needs none of it). Until then only its button listens.
import type { StagesElements, StagesHost, StagesMode } from './stages';
import type { BuildResult } from '../../build';
import { onDemand } from '../page';

/** A {@link StagesMode} on `els` that loads with its first showing. */
export class LazyStagesMode {
  private mode: StagesMode | undefined;
  private readonly toggled = () => this.show();

  constructor(
    private readonly els: StagesElements,
    private readonly host: StagesHost,
  ) {
    els.toggle.addEventListener('click', this.toggled);
  }

  /** As {@link StagesMode.open}. */
  get open(): boolean {
    return this.mode?.open ?? false;
  }

  /** As {@link StagesMode.show}; the first call loads Stages. */
  show(): void {
    if (this.mode) return this.mode.show();
    void this.load().then((mode) => mode?.show());
  }

  /** As {@link StagesMode.close}. */
  close(): void {
    this.mode?.close();
  }

  /** As {@link StagesMode.delivered}: nothing to grow before Stages has loaded (it reads the plant on screen when shown). */
  delivered(result: BuildResult): void {
    this.mode?.delivered(result);
  }

  /** As {@link StagesMode.setLighting}: read from the host when Stages is shown. */
  setLighting(lit: boolean): void {
    this.mode?.setLighting(lit);
  }

  private readonly loaded = onDemand(async () => {
    const { StagesMode } = await import('./stages');
    this.els.toggle.removeEventListener('click', this.toggled); // Stages listens to its button now
    this.mode = new StagesMode(this.els, this.host);
    return this.mode;
  });

  /** Stages, loaded (undefined, said in the console, when it could not load: the next click tries again). */
  private load(): Promise<StagesMode | undefined> {
    return this.loaded().catch((error: unknown) => {
      console.error('Stages could not load:', error);
      return undefined;
    });
  }
}
