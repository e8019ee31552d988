// The movie dialog, from the Download menu: the growth (and a turntable) as a WebM or MP4 video, an
// animated GIF or a numbered PNG sequence, at a size and frame rate, over a range of growth time;
// a progress bar with the frame count and Cancel; the file named after the grammar. Made here, not
// in index.html: it loads with the Download menu's code, after the first plant.
import type { PictureLook, PlantView } from '../../../view';
import { saveFile } from '../../files/save-file';
import { el } from '../../page/make-element';
import { fileSize } from '../downloads';
import { FORMATS, SIZE_PRESETS, movieFileName, movieSeconds, planMovie, type MovieFormat, type MovieOptions, type MoviePlan } from './movie-plan';
import { derivedGrowth, type DerivedStudio } from './derived-growth';
import { recordMovie, type RecordingMovie } from './record-movie';
import { growthSpanOf, viewScene, type FilmedScene } from './view-scene';
import './movie-dialog.css';

/** The dialog's controls. */
interface MovieControls {
  dialog: HTMLDialogElement;
  format: HTMLSelectElement;
  size: HTMLSelectElement;
  width: HTMLInputElement;
  height: HTMLInputElement;
  fps: HTMLSelectElement;
  timing: HTMLSelectElement;
  seconds: HTMLInputElement;
  from: HTMLInputElement;
  to: HTMLInputElement;
  range: HTMLFieldSetElement;
  rangeNote: HTMLElement;
  background: HTMLSelectElement;
  turntable: HTMLInputElement;
  summary: HTMLElement;
  progress: HTMLProgressElement;
  record: HTMLButtonElement;
  cancel: HTMLButtonElement;
}

function options(select: HTMLSelectElement, entries: [value: string, label: string][]): HTMLSelectElement {
  select.replaceChildren(...entries.map(([value, label]) => el('option', { value, textContent: label })));
  return select;
}

/** A labelled field: the label wraps its control. */
function field(label: string, control: HTMLElement, after = ''): HTMLLabelElement {
  return el('label', { className: 'field' }, `${label} `, control, after);
}

const number = (testid: string, value: string, min: string, step: string) =>
  el('input', { type: 'number', value, min, step, testid, inputMode: 'decimal' });

/** Builds the dialog (closed) in `document.body`. */
function makeDialog(): MovieControls {
  const c: MovieControls = {
    dialog: el('dialog', { className: 'movie-dialog', testid: 'movie-dialog' }),
    format: el('select', { testid: 'movie-format' }),
    size: el('select', { testid: 'movie-size' }),
    width: number('movie-width', '1280', '16', '2'),
    height: number('movie-height', '720', '16', '2'),
    fps: el('select', { testid: 'movie-fps' }),
    timing: options(el('select', { testid: 'movie-timing' }), [
      ['per-step', 'seconds per step'],
      ['duration', 'seconds in all'],
    ]),
    seconds: number('movie-seconds', '1', '0', 'any'),
    from: number('movie-from', '0', '0', 'any'),
    to: number('movie-to', '0', '0', 'any'),
    range: el('fieldset', { className: 'movie-range' }),
    rangeNote: el('p', { className: 'hint', id: 'movie-range-note' }),
    background: options(el('select', { testid: 'movie-background' }), [
      ['white', 'white'],
      ['view', 'as the view, with the grid'],
    ]),
    turntable: el('input', { type: 'checkbox', testid: 'movie-turntable' }),
    summary: el('p', { className: 'movie-summary', testid: 'movie-summary', role: 'status' }),
    progress: el('progress', { testid: 'movie-progress', hidden: true, value: 0, max: 1 }),
    record: el('button', { type: 'button', className: 'primary', testid: 'movie-record', textContent: 'Record' }),
    cancel: el('button', { type: 'button', testid: 'movie-cancel', textContent: 'Cancel', hidden: true }),
  };
  const title = el('h2', { id: 'movie-title', textContent: 'Movie of the growth' });
  const close = el('form', { method: 'dialog' }, el('button', { type: 'submit', className: 'quiet', textContent: 'Close', testid: 'movie-close' }));
  c.dialog.setAttribute('aria-labelledby', title.id);
  c.progress.setAttribute('aria-label', 'Frames recorded');
  c.range.append(el('legend', { textContent: 'Growth time, in steps' }), field('From', c.from), field('to', c.to), c.rangeNote);
  c.from.setAttribute('aria-describedby', c.rangeNote.id);
  options(c.size, [...SIZE_PRESETS.map(({ width, height, label }): [string, string] => [`${width}x${height}`, label]), ['', 'Custom']]);
  c.dialog.append(
    el('header', { className: 'dialog-header' }, title, close),
    el(
      'div',
      { className: 'movie-body' },
      el('div', { className: 'movie-row' }, field('Format', c.format), field('Frame rate', c.fps, ' fps')),
      el('div', { className: 'movie-row' }, field('Size', c.size), field('Width', c.width), field('Height', c.height)),
      el('div', { className: 'movie-row' }, field('Length', c.seconds), el('span', { className: 'field' }, c.timing)),
      c.range,
      el('div', { className: 'movie-row' }, field('Background', c.background), el('label', { className: 'movie-check' }, c.turntable, ' Turntable: the camera turns once around the plant')),
      c.summary,
      el('div', { className: 'movie-actions' }, c.progress, c.cancel, c.record),
    ),
  );
  c.timing.setAttribute('aria-label', 'Length in');
  document.body.append(c.dialog);
  return c;
}

/** The dialog's choices, read (numbers not checked: see `planMovie`). */
function chosen(c: MovieControls): MovieOptions {
  return {
    format: c.format.value as MovieFormat,
    width: Number(c.width.value),
    height: Number(c.height.value),
    fps: Number(c.fps.value),
    timing: { kind: c.timing.value as 'duration' | 'per-step', seconds: Number(c.seconds.value) },
    from: Number(c.from.value),
    to: Number(c.to.value),
    turntable: c.turntable.checked,
  };
}

/** `300 frames · 10 s · 1280 × 720 · turntable`. */
function describePlan(plan: MoviePlan): string {
  const seconds = new Intl.NumberFormat('en-US', { maximumFractionDigits: 2 }).format(movieSeconds(plan.frames, plan.fps));
  const range = plan.from === plan.to ? 'the whole plant' : `steps ${plan.from} to ${plan.to}`;
  return `${plan.frames} ${plan.frames === 1 ? 'frame' : 'frames'} · ${seconds} s · ${plan.width} × ${plan.height} · ${range}${plan.turntable ? ' · turntable' : ''}`;
}

/** The frame rate offered nearest `fps` for `format`. */
function nearestRate(format: MovieFormat, fps: number): number {
  return FORMATS[format].rates.reduce((best, rate) => (Math.abs(rate - fps) < Math.abs(best - fps) ? rate : best));
}

/** Where the dialog finds the plant on screen. */
export interface MovieSource {
  view: PlantView;
  /** The name files of the plant on screen are saved under (none before the first plant). */
  name(): string | undefined;
  /** The studio's timeline and builds: a timed or stepwise grammar is filmed derived at each frame's t, as the timeline shows it. */
  studio: DerivedStudio;
}

/** The movie dialog, made on first use; `open` shows it for the plant on screen. */
export class MovieDialog {
  private readonly c = makeDialog();
  private recording: RecordingMovie | undefined;
  private span: number | null = null;

  constructor(private readonly source: MovieSource) {
    const c = this.c;
    this.fillFormats({ webm: true, mp4: false });
    c.format.addEventListener('change', () => this.formatChanged());
    c.size.addEventListener('change', () => {
      const [width, height] = c.size.value.split('x');
      if (width && height) [c.width.value, c.height.value] = [width, height];
      this.update();
    });
    for (const input of [c.width, c.height]) input.addEventListener('input', () => ((c.size.value = ''), this.update()));
    for (const input of [c.fps, c.timing, c.seconds, c.from, c.to, c.turntable]) input.addEventListener('input', () => this.update());
    c.record.addEventListener('click', () => void this.record());
    c.cancel.addEventListener('click', () => this.recording?.cancel());
    // Closing the dialog (Close, Escape) while recording cancels the movie.
    c.dialog.addEventListener('close', () => this.recording?.cancel());
  }

  /** The formats, each video offered only where the browser encodes it (WebCodecs; H.264 for MP4). */
  private fillFormats(encodes: Record<'webm' | 'mp4', boolean>): void {
    const kept = this.c.format.value || 'webm';
    const formats = (['webm', 'mp4', 'gif', 'png'] as const).filter((f) => (f !== 'webm' && f !== 'mp4') || encodes[f]);
    options(
      this.c.format,
      formats.map((f) => [f, `${FORMATS[f].label} (${movieFileName('…', f).slice(1)})`]),
    );
    this.c.format.value = kept;
    if (this.c.format.value === '') this.c.format.value = formats[0];
    this.fillRates();
  }

  private fillRates(): void {
    const format = this.c.format.value as MovieFormat;
    const before = Number(this.c.fps.value) || 30;
    options(this.c.fps, FORMATS[format].rates.map((rate) => [String(rate), String(rate)]));
    this.c.fps.value = String(nearestRate(format, before));
  }

  /** A GIF defaults small (slides, learning platforms); a video to HD. */
  private formatChanged(): void {
    const c = this.c;
    const gif = c.format.value === 'gif';
    const size = gif ? '480x270' : '1280x720';
    if (c.size.value !== '' || gif) {
      c.size.value = size;
      [c.width.value, c.height.value] = size.split('x');
    }
    this.fillRates();
    if (gif) c.fps.value = '20';
    this.update();
  }

  /** Shows the dialog for the plant on screen: the range its whole growth, 0 to N. */
  async open(): Promise<void> {
    const c = this.c;
    if (!c.dialog.open) c.dialog.showModal();
    if (this.recording) return;
    this.span = this.source.studio.timeline.timedSpan() ?? growthSpanOf(this.source.view);
    const growing = this.span !== null;
    c.range.disabled = !growing;
    c.from.max = c.to.max = String(this.span ?? 0);
    c.from.value = '0';
    c.to.value = String(this.span ?? 0);
    c.rangeNote.textContent = growing
      ? `The plant grows from step 0 to ${this.span}.`
      : 'This plant was built without growth times (show the timeline first): the movie shows it whole, turning.';
    if (!growing) {
      c.turntable.checked = true;
      c.timing.value = 'duration';
      if (Number(c.seconds.value) < 2) c.seconds.value = '6';
    }
    this.update();
    const { canEncode } = await import('./video-writer');
    const [webm, mp4] = await Promise.all([canEncode('webm', 1280, 720, 30), canEncode('mp4', 1280, 720, 30)]);
    const before = c.format.value;
    this.fillFormats({ webm, mp4 });
    if (c.format.value !== before) this.formatChanged(); // (a video this browser cannot encode was chosen)
    else this.update();
  }

  /** The plan of the choices, shown in the summary (or what is wrong with them). */
  private update(): MoviePlan | undefined {
    const planned = planMovie(chosen(this.c), this.span, this.source.view.maxPictureSide());
    const { summary, record } = this.c;
    summary.textContent = planned.ok ? describePlan(planned.plan) : planned.message;
    summary.dataset.state = planned.ok ? 'ok' : 'error';
    record.disabled = !planned.ok || this.recording !== undefined;
    return planned.ok ? planned.plan : undefined;
  }

  /** Records the movie of the choices, and saves it. */
  private async record(): Promise<void> {
    const plan = this.update();
    const name = this.source.name();
    if (!plan || this.recording || name === undefined) return;
    const c = this.c;
    const look: PictureLook = { background: c.background.value as PictureLook['background'] };
    this.busy(true, plan.frames);
    const started = performance.now();
    let scene: FilmedScene | undefined;
    try {
      const { studio, view } = this.source;
      studio.timeline.pose(true); // the movie poses the plant, the timeline asks nothing meanwhile
      scene = await viewScene(view, look, derivedGrowth(studio));
      this.recording = recordMovie(plan, scene, name, (done, frames) => {
        c.progress.value = done;
        this.say('busy', `Frame ${done} of ${frames}…`);
      });
      const file = await this.recording.done;
      if (!file) return this.say('cancelled', 'Cancelled: nothing was saved');
      const fileName = movieFileName(name, plan.format);
      saveFile(file, fileName, file.type);
      const seconds = ((performance.now() - started) / 1000).toFixed(1);
      this.say('done', `Saved ${fileName} · ${plan.frames} frames · ${fileSize(file.size)} (written in ${seconds} s)`);
    } catch (error) {
      console.error('The movie failed:', error);
      this.say('error', `The movie failed: ${error instanceof Error ? error.message : String(error)}`);
    } finally {
      this.source.studio.timeline.pose(false);
      scene?.close();
      this.recording = undefined;
      this.busy(false, plan.frames);
    }
  }

  private busy(on: boolean, frames: number): void {
    const c = this.c;
    for (const control of [c.format, c.size, c.width, c.height, c.fps, c.timing, c.seconds, c.background, c.turntable]) control.disabled = on;
    c.range.disabled = on || this.span === null;
    c.record.disabled = on;
    c.cancel.hidden = !on;
    c.progress.hidden = !on;
    c.progress.max = frames;
    c.progress.value = 0;
    c.dialog.dataset.state = on ? 'busy' : 'idle';
    if (on) c.cancel.focus();
    else c.record.focus();
  }

  private say(state: 'busy' | 'done' | 'cancelled' | 'error', text: string): void {
    this.c.summary.textContent = text;
    this.c.summary.dataset.state = state;
  }
}
