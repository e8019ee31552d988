// Whether the view frames each new plant: the holds on the frame (branch editing, Play), the
// framing asked for the next plant, and the "Refit" hint when a plant was not framed.

/** The view's following of the plant, apart from the camera (see `PlantView.follow`). */
export class FrameFollowing {
  /** Frame the next plant shown, even if the camera was moved (a new grammar was opened). */
  frameNext = false;
  /** Who holds the frame now (e.g. `editing`, `play`): while anyone does, new plants keep it. */
  private readonly holders = new Set<string>();
  private refitHinted = false;
  private readonly refitListeners = new Set<(shown: boolean) => void>();

  /** Holds the frame for `holder` (`on`) or lets it go. */
  hold(holder: string, on: boolean): void {
    if (on) this.holders.add(holder);
    else this.holders.delete(holder);
  }

  /** Whether anyone holds the frame. */
  get held(): boolean {
    return this.holders.size > 0;
  }

  /** Calls `listener` when the hint shows (`true`) or goes (`false`); returns the function that stops it. */
  onRefitHint(listener: (shown: boolean) => void): () => void {
    this.refitListeners.add(listener);
    return () => this.refitListeners.delete(listener);
  }

  /** Shows the hint or takes it away (its listeners hear of a change only). */
  hintRefit(shown: boolean): void {
    if (shown === this.refitHinted) return;
    this.refitHinted = shown;
    for (const listener of this.refitListeners) listener(shown);
  }
}
