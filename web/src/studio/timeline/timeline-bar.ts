// The timeline bar under the view (issue 45): Play / Pause, the growth time t on a slider (with
// the step growing and how far), the speed, Loop, the range played (from, to), the camera (on
// the final plant, or following the growth) and a turntable. It drives the view's growth time
// (`PlantView.setGrowthTime`: a uniform, no build) through a `Timeline` (plant-controls). Keys:
// on the slider ← → a step (Shift: a tenth), Home / End the range's ends, Space play / pause; on
// the view Space too; Alt+P anywhere. Loaded after the first plant, or by the first Play.
import { cleanGrowth, type SharedGrowth } from '../../share';
import { GrowthShow, Timeline, TIMELINE_SPEEDS, type TimelineState } from '../../plant-controls/timeline';
import type { GrowthCamera } from '../../view';
import type { TimelineElements, TimelineStudio } from './lazy-timeline';
import { PanelPace, type HandOver } from './panel-pace';
import type { playStop } from '../derivation/breakpoints';
import './timeline-bar.css';

/** Degrees the turntable turns the camera for each step of growth played. */
export const TURNTABLE_DEGREES_PER_STEP = 45;
/** Who holds the view's frame while a timed or stepwise grammar is derived at t with the camera on the final plant. */
const FRAME_HOLDER = 'timeline';

/** t as the bar writes it: two decimals. */
export function timeText(t: number): string {
  return t.toFixed(2);
}

/**
 * What the bar says of t in a plant of `span` steps: the step growing (⌈t⌉, the step whose new
 * organs are growing in; t = n is step n's plant whole) and the time.
 */
export function growthLabel(t: number, span: number | null): string {
  if (span === null) return `t ${timeText(t)}`;
  if (t >= span) return `t ${timeText(span)} of ${span} · whole plant`;
  const step = Math.ceil(t);
  return `t ${timeText(t)} of ${span} · step ${step}${t === step ? '' : ' growing'}`;
}

function make<K extends keyof HTMLElementTagNameMap>(tag: K, attributes: Record<string, string>, text?: string): HTMLElementTagNameMap[K] {
  const e = document.createElement(tag);
  for (const [name, value] of Object.entries(attributes)) e.setAttribute(name, value);
  if (text !== undefined) e.textContent = text;
  return e;
}

/** A labelled control: `<label>text control</label>`. */
function labelled(text: string, control: HTMLElement, title: string): HTMLLabelElement {
  const label = make('label', { class: 'field', title });
  label.append(text, control);
  return label;
}

/** The bar's controls. */
interface BarControls {
  play: HTMLButtonElement;
  slider: HTMLInputElement;
  time: HTMLOutputElement;
  speed: HTMLSelectElement;
  loop: HTMLInputElement;
  from: HTMLInputElement;
  to: HTMLInputElement;
  camera: HTMLSelectElement;
  turntable: HTMLInputElement;
}

/** Makes the bar's controls in `bar` (empty before). */
function barControls(bar: HTMLElement): BarControls {
  const play = make('button', { type: 'button', class: 'play', 'data-testid': 'timeline-play', 'aria-pressed': 'false', title: 'Play the growth (Space on the view, Alt+P)' }, 'Play');
  const slider = make('input', { type: 'range', min: '0', max: '1', step: '0.01', value: '1', 'data-testid': 'timeline-slider', 'aria-label': 'Growth time, in steps' });
  slider.title = '← → a step, Shift+← → a tenth, Home / End the range played';
  const time = make('output', { 'data-testid': 'timeline-time', class: 'timeline-time' });
  const speed = make('select', { 'data-testid': 'timeline-speed' });
  for (const s of TIMELINE_SPEEDS) speed.append(make('option', { value: String(s) }, `${s}×`));
  speed.value = '1';
  const loop = make('input', { type: 'checkbox', 'data-testid': 'timeline-loop' });
  const from = make('input', { type: 'number', min: '0', step: '0.5', value: '0', inputmode: 'decimal', 'data-testid': 'timeline-from' });
  const to = make('input', { type: 'number', min: '0', step: '0.5', inputmode: 'decimal', 'data-testid': 'timeline-to' });
  const camera = make('select', { 'data-testid': 'timeline-camera' });
  camera.append(make('option', { value: 'final' }, 'final plant'), make('option', { value: 'follow' }, 'follow growth'));
  const turntable = make('input', { type: 'checkbox', 'data-testid': 'timeline-turntable' });
  const range = make('span', { class: 'timeline-range', role: 'group', 'aria-label': 'Range played' });
  range.append(labelled('From', from, 'Play from this time (in steps)'), labelled('to', to, 'Play up to this time (empty: the whole plant)'));
  // The rest in a menu: the bar stays one line under a short view (a phone, a projector at 200 %).
  const menu = make('details', { class: 'downloads tool-menu timeline-menu', 'data-testid': 'timeline-menu' });
  const summary = make('summary', { title: 'Speed, loop, range, camera, turntable', 'aria-label': 'Options of the timeline' }, 'Options ▾');
  const panel = make('div', { class: 'download-menu timeline-options' });
  panel.append(
    labelled('Speed', speed, 'Steps of growth per second'),
    labelled('Loop', loop, 'Start again at the range’s start'),
    range,
    labelled('Camera', camera, 'While the growth plays: framed on the whole plant, or following what has grown'),
    labelled('Turntable', turntable, `The camera turns about the plant as it grows (${TURNTABLE_DEGREES_PER_STEP}° a step)`),
  );
  menu.append(summary, panel);
  menu.addEventListener('keydown', (event) => {
    if (event.key !== 'Escape' || !menu.open) return;
    menu.open = false;
    summary.focus();
  });
  document.addEventListener('pointerdown', (event) => {
    if (menu.open && !menu.contains(event.target as Node)) menu.open = false;
  });
  const track = make('span', { class: 'timeline-track' });
  track.append(slider, time);
  bar.replaceChildren(play, track, menu);
  loop.parentElement!.classList.add('check');
  turntable.parentElement!.classList.add('check');
  return { play, slider, time, speed, loop, from, to, camera, turntable };
}

/** What the bar asks of the studio's builds. */
export interface TimelineBuilds {
  /** Builds carry growth arrays from now on. */
  want(): void;
  /** A timed grammar's builds derive it at growth time `t`, a stepwise one's at ⌊t⌋ (null: at its iterations). */
  deriveAt(t: number | null): void;
}

/** What the timeline bar asks of the debugger's breakpoints. */
type PlayStop = Pick<typeof playStop, 'at' | 'paused'>;

/** The timeline bar and the timeline it drives. */
export class TimelineBar {
  readonly timeline: Timeline;
  /** The plant at t: a timed grammar derived at t (builds paced), any other grown on the GPU. */
  private readonly growth: GrowthShow;
  private readonly controls: BarControls;
  /** The user (or a link) has put the timeline somewhere: new plants show that time, not whole. */
  private engaged = false;
  /** A movie poses the plant: the bar shows no time of its own meanwhile ({@link pose}). */
  private posed = false;
  /** The last t shown while playing, for the turntable. */
  private lastT: number | null = null;
  /** How the panels follow the builds while the growth plays. */
  private readonly panels = new PanelPace(() => this.timeline.playing);

  constructor(
    private readonly els: TimelineElements,
    private readonly studio: TimelineStudio,
    private readonly builds: TimelineBuilds,
  ) {
    const { view } = studio;
    this.growth = new GrowthShow(view, { timedSpan: () => studio.timedSpan(), deriveAt: (t) => builds.deriveAt(t), busy: () => studio.busy() });
    this.timeline = new Timeline({ span: () => this.growth.span(), show: (t) => this.show(t) });
    this.controls = barControls(els.bar);
    els.bar.hidden = false;
    this.timeline.onChange((state) => {
      if (this.breakAt(state)) return; // (paused there: the pause's own change has rendered)
      if (!state.playing) this.panels.flush(); // paused: the panels show the plant on screen
      this.render(state);
    });
    this.listen();
    void import('../derivation/breakpoints').then(({ playStop }) => (this.stop = playStop));
    view.onPlantShown(() => this.plantShown());
    this.plantShown();
  }

  /** The t last shown while playing (null: paused), to see Play cross a breakpoint's step. */
  private playedT: number | null = null;
  /** The debugger's breakpoints (the String tab's), once their code is there. */
  private stop: PlayStop | undefined;

  /** Pauses Play where it crosses the debugger's breakpoint (the String tab's), at its step: true when it did. */
  private breakAt(state: TimelineState): boolean {
    const before = this.playedT;
    this.playedT = state.playing ? state.t : null;
    const at = this.stop?.at() ?? null;
    if (at === null || before === null || !state.playing || !(before < at && at <= state.t)) return false;
    this.timeline.pause();
    this.timeline.seek(at);
    this.stop?.paused();
    return true;
  }

  private listen(): void {
    const { play, slider, speed, loop, from, to, camera } = this.controls;
    play.addEventListener('click', () => this.toggle());
    slider.addEventListener('input', () => this.seek(slider.valueAsNumber));
    slider.addEventListener('keydown', (event) => this.onKey(event));
    this.studio.view.canvas.addEventListener('keydown', (event) => {
      if (event.key !== ' ' || event.altKey || event.ctrlKey || event.metaKey) return;
      event.preventDefault();
      this.toggle();
    });
    speed.addEventListener('change', () => this.timeline.setSpeed(Number(speed.value)));
    loop.addEventListener('change', () => this.timeline.setLoop(loop.checked));
    const range = () => this.timeline.setRange(from.valueAsNumber || 0, to.value.trim() === '' ? null : to.valueAsNumber);
    from.addEventListener('change', range);
    to.addEventListener('change', range);
    camera.addEventListener('change', () => this.studio.view.setGrowthCamera(camera.value as GrowthCamera));
  }

  /** The slider's keys: ← → a step (Shift: a tenth), Home / End the range's ends, Space play / pause. */
  private onKey(event: KeyboardEvent): void {
    const fine = event.shiftKey ? 0.1 : 1;
    const state = this.timeline.state;
    const moves: Record<string, () => void> = {
      ArrowLeft: () => this.step(-fine),
      ArrowDown: () => this.step(-fine),
      ArrowRight: () => this.step(fine),
      ArrowUp: () => this.step(fine),
      Home: () => this.seek(state.from),
      End: () => this.seek(state.to),
      ' ': () => this.toggle(),
    };
    const move = moves[event.key];
    if (!move || event.altKey || event.ctrlKey || event.metaKey) return;
    event.preventDefault();
    move();
  }

  /** Play / pause; the first use asks for growth arrays (the plant waits, playing, for them). */
  toggle(): void {
    this.engage();
    this.timeline.toggle();
  }

  private seek(t: number): void {
    this.engage();
    this.timeline.pause();
    this.timeline.seek(t);
  }

  private step(delta: number): void {
    this.engage();
    this.timeline.stepBy(delta);
  }

  private engage(): void {
    this.engaged = true;
    this.builds.want();
  }

  /**
   * Shows growth time `t` (the whole plant at the span's end), in the Lines mode as in the Tubes
   * mode. A timed grammar is derived at t, a stepwise one at ⌊t⌋ (a build, asked for once the one
   * under way has arrived); any other grows on the GPU from its whole plant's mesh.
   */
  private show(t: number): void {
    if (this.posed) return;
    const { view } = this.studio;
    this.growth.show(t);
    // Each derived plant would be framed anew, and a plant growing would seem to stand still: the
    // camera stays on the whole plant it framed (unless it follows the growth).
    const timedSpan = this.studio.timedSpan();
    const derived = timedSpan !== null && t < timedSpan;
    view.holdFrame(FRAME_HOLDER, derived && this.controls.camera.value === 'final');
    if (this.controls.turntable.checked && this.timeline.playing && this.lastT !== null && t > this.lastT) {
      view.turn((t - this.lastT) * TURNTABLE_DEGREES_PER_STEP);
    }
    this.lastT = this.timeline.playing ? t : null;
  }

  /** A plant is on screen: the slider spans its steps; the time it was at is shown again. */
  plantShown(): void {
    const span = this.studio.view.growthSpan();
    if (this.engaged) this.timeline.refresh();
    else if (span !== null) this.timeline.seek(span);
    this.render(this.timeline.state);
  }

  /**
   * A build was delivered: its steps are shown (the slider's end, the label). A time wanted while
   * it was under way is derived now, and so is the time shown (a link's) if this build is the
   * first to say its grammar is timed (its plant was shown before the studio knew).
   */
  stepsChanged(): void {
    if (this.posed) return;
    if (this.engaged) this.timeline.refresh();
    this.growth.delivered();
    this.render(this.timeline.state);
  }

  /**
   * A movie poses the plant (`on`: playing stops, and no time of the bar's is shown or asked for
   * until it is done) or is done.
   */
  pose(on: boolean): void {
    this.posed = on;
    if (on) this.timeline.pause();
  }

  /** A delivered build for the panels: at once, or while playing at their pace ({@link PanelPace}). */
  handOver(build: HandOver): void {
    this.panels.offer(build);
  }

  /** Another text is opened: playing stops and the plant shows whole. */
  clear(): void {
    this.timeline.pause();
    this.engaged = false;
    this.studio.view.holdFrame(FRAME_HOLDER, false);
    this.studio.view.setGrowthTime(null);
    this.render(this.timeline.state);
  }

  /** Shows the state: Play's label and pressed state (both Plays), the slider, t and the step. */
  private render(state: TimelineState): void {
    const { play, slider, time } = this.controls;
    const steps = state.span ?? this.studio.steps() ?? 0;
    const t = this.engaged ? state.t : steps;
    // (Called every frame while playing: only what changed is written, since a write of the same
    // text or attribute still makes the page lay out, paint and hit-test again.)
    for (const button of [play, this.els.play]) {
      setAttribute(button, 'aria-pressed', String(state.playing));
      setProperty(button, 'textContent', state.playing ? 'Pause' : 'Play');
    }
    setProperty(slider, 'max', String(Math.max(steps, 0.01)));
    setProperty(slider, 'value', String(Math.min(t, steps)));
    const label = state.span === null && this.engaged ? `${growthLabel(t, null)} (growth loading…)` : growthLabel(t, steps);
    setAttribute(slider, 'aria-valuetext', label);
    setProperty(time, 'value', label);
    setAttribute(this.els.bar, 'data-t', String(t));
  }


  /** What a share link keeps: the time (once used), speed, range, loop, camera, turntable; none at their defaults. */
  toShared(): SharedGrowth | undefined {
    const state = this.timeline.state;
    const shared: SharedGrowth = {};
    if (this.engaged) shared.t = state.t;
    if (state.speed !== 1) shared.speed = state.speed;
    if (state.from > 0) shared.from = state.from;
    const to = this.controls.to.value.trim();
    if (to !== '') shared.to = Number(to);
    if (state.loop) shared.loop = true;
    if (this.controls.camera.value === 'follow') shared.camera = 'follow';
    if (this.controls.turntable.checked) shared.turntable = true;
    return cleanGrowth(shared);
  }

  /** A link's timeline (checked again: it may come from anywhere). */
  applyShared(shared: SharedGrowth): void {
    const growth = cleanGrowth(shared);
    if (!growth) return;
    const { speed, loop, from, to, camera, turntable } = this.controls;
    if (growth.speed !== undefined) {
      this.timeline.setSpeed(growth.speed);
      if (!TIMELINE_SPEEDS.some((s) => s === growth.speed)) speed.append(make('option', { value: String(growth.speed) }, `${growth.speed}×`));
      speed.value = String(growth.speed);
    }
    loop.checked = growth.loop ?? false;
    this.timeline.setLoop(loop.checked);
    from.value = String(growth.from ?? 0);
    to.value = growth.to === undefined ? '' : String(growth.to);
    this.timeline.setRange(growth.from ?? 0, growth.to ?? null);
    camera.value = growth.camera ?? 'final';
    this.studio.view.setGrowthCamera(growth.camera ?? 'final');
    turntable.checked = growth.turntable ?? false;
    if (growth.t !== undefined) {
      this.engage();
      this.timeline.seek(growth.t);
    }
    if (growth.playing) this.toggle();
  }
}

/** Sets an element's property to `value` unless it has it already. */
function setProperty<E extends HTMLElement, K extends keyof E>(element: E, key: K, value: E[K]): void {
  if (element[key] !== value) element[key] = value;
}

/** Sets an element's attribute to `value` unless it has it already. */
function setAttribute(element: Element, name: string, value: string): void {
  if (element.getAttribute(name) !== value) element.setAttribute(name, value);
}
