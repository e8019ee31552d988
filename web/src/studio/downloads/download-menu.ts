// The Download menu: a button per model format, written in an export worker with its progress and
// a Cancel button on the status line (the page stays responsive), and the picture settings with
// the PNG of the view and the SVG drawing (written by the export worker too). One download at a
// time: the menu is disabled meanwhile.
import { MODEL_FORMATS, type ExportOptions, type ModelFormat, type SvgLook } from '../../core';
import type { PictureLook, PlantView } from '../../view';
import { afterPaint, fileSize, paperPixels, pictureSize, withResolution, type PaperChoice } from './downloads';
import { saveFile } from '../files/save-file';
import { createExportWorker, describeProgress, runExport } from './export-client';
// Loaded on demand: it imports other areas' files, not their indexes, which would bring their
// wiring into its chunk's graph (and split the first load into more files).
import { closeLikeAMenu } from '../page/menus';
import type { DerivedStudio } from './movie/derived-growth';

/** The menu and the export's status (see index.html). */
export interface DownloadMenuElements {
  menu: HTMLDetailsElement;
  /** Where the model formats' buttons go. */
  modelDownloads: HTMLElement;
  pngWidth: HTMLInputElement;
  pngHeight: HTMLInputElement;
  downloadPng: HTMLButtonElement;
  /** The SVG drawing, in the picture settings (the model formats' loop leaves SVG out). */
  downloadSvg: HTMLButtonElement;
  /** A sheet of paper the picture fills (empty: the width and height typed). */
  pngPaper: HTMLSelectElement;
  pngDpi: HTMLSelectElement;
  pngBackground: HTMLSelectElement;
  /** The Lines mode's width in the picture, in its pixels. */
  pngLineWidth: HTMLInputElement;
  exportStatus: HTMLElement;
  exportProgress: HTMLProgressElement;
  exportCancel: HTMLButtonElement;
}

/** The plant a model download writes: its text and options (with its branch edits). */
export interface DownloadedPlant {
  source: string;
  options: ExportOptions;
  /** The name its files are saved under, without extension (see `figureName`). */
  name: string;
}

/** The state of the last download. */
export type ExportState = 'busy' | 'done' | 'cancelled' | 'error';

/** Shows the state of the last download next to the build status. */
export function showExportStatus(element: HTMLElement, state: ExportState, text: string): void {
  element.textContent = text;
  element.dataset.state = state;
}

/**
 * Fills the Download menu; `shown` is the plant on screen (none before the first good build);
 * `studio`, its timeline and builds, for movies of a plant derived at t.
 */
export function installDownloads(els: DownloadMenuElements, view: PlantView, shown: () => DownloadedPlant | undefined, studio: MovieStudio): void {
  const menuButtons = (): HTMLButtonElement[] => [...els.menu.querySelectorAll('button')];
  const busy = (on: boolean) => {
    menuButtons().forEach((b) => (b.disabled = on));
    els.exportProgress.hidden = !on;
    els.exportCancel.hidden = !on;
    if (on) els.exportProgress.removeAttribute('value'); // indeterminate until the first stage
  };
  let cancel: (() => void) | undefined;
  els.exportCancel.addEventListener('click', () => cancel?.());
  /** Runs one download; `save` returns the status text, or null when cancelled. */
  const download = async (what: string, save: () => Promise<string | null>): Promise<void> => {
    if (menuButtons().some((b) => b.disabled)) return;
    els.menu.open = false;
    busy(true);
    showExportStatus(els.exportStatus, 'busy', `Exporting ${what}…`);
    try {
      const done = await save();
      showExportStatus(els.exportStatus, done === null ? 'cancelled' : 'done', done ?? `Export of ${what} cancelled`);
    } catch (error) {
      console.error(`Export of ${what} failed:`, error);
      showExportStatus(els.exportStatus, 'error', `Export of ${what} failed: ${error instanceof Error ? error.message : String(error)}`);
    } finally {
      cancel = undefined;
      busy(false);
    }
  };
  /** Writes the plant shown as `format`; `more`: the SVG's look, or the glTF's growth animation. */
  const downloadModel = (format: ModelFormat, label: string, more: Pick<ExportOptions, 'svg' | 'animate'> = {}): Promise<void> =>
    download(label, async () => {
      const plant = shown();
      if (!plant) throw new Error('no plant yet');
      const name = more.animate ? `${plant.name}-growth` : plant.name;
      const options = { ...plant.options, name, ...more };
      const running = runExport(createExportWorker, { source: plant.source, format, options }, (progress) => {
        els.exportProgress.max = progress.count;
        els.exportProgress.value = progress.index + 1;
        showExportStatus(els.exportStatus, 'busy', describeProgress(label, progress));
      });
      cancel = running.cancel;
      const outcome = await running.done;
      if (outcome.kind === 'cancelled') return null;
      if (outcome.kind === 'failed') {
        throw new Error(outcome.message);
      }
      saveFile(outcome.file.bytes, outcome.file.fileName, outcome.file.mimeType);
      return `Saved ${outcome.file.fileName} · ${fileSize(outcome.file.bytes.length)}`;
    });
  for (const { format, label, file } of MODEL_FORMATS) {
    if (format === 'svg') continue; // under the picture settings
    const button = document.createElement('button');
    button.type = 'button';
    button.className = 'menu-item';
    button.dataset.testid = `download-${format}`;
    button.append(label, Object.assign(document.createElement('span'), { className: 'file-type', textContent: file }));
    button.addEventListener('click', () => void downloadModel(format, label));
    els.modelDownloads.append(button);
  }
  // The growth as a glTF animation (morph targets keyed in time: 1 s per step), which three.js's
  // AnimationMixer, Blender and glTF viewers play.
  const animated = document.createElement('button');
  animated.type = 'button';
  animated.className = 'menu-item';
  animated.dataset.testid = 'download-glb-growth';
  animated.title = 'The plant growing, as a glTF animation that three.js, Blender and glTF viewers play';
  animated.append('glTF 2.0, growth animated', Object.assign(document.createElement('span'), { className: 'file-type', textContent: '.glb' }));
  animated.addEventListener('click', () => void downloadModel('glb', 'glTF growth animation', { animate: true }));
  els.modelDownloads.append(animated);
  installMovie(els, { view, shown, studio });
  closeLikeAMenu(els.menu);
  installPictureSize(els);
  els.downloadPng.addEventListener('click', () => {
    const settings = pictureSettings(els, 'PNG', view.maxPictureSide());
    if (!settings.ok) {
      showExportStatus(els.exportStatus, 'error', settings.message);
      return;
    }
    const { size, dpi, lineWidth, background } = settings;
    const look: PictureLook = { background, lineWidth };
    const name = `${shown()?.name ?? 'plant'}.png`;
    // The picture is drawn by the page's WebGL context: it cannot move to a worker (it is one draw).
    void download(`PNG ${size.width} × ${size.height}`, async () => {
      await afterPaint(); // the status shows before the draw
      const drawn = await view.snapshot(size.width, size.height, look);
      const png = withResolution(new Uint8Array(await drawn.arrayBuffer()), dpi);
      saveFile(png, name, 'image/png');
      return `Saved ${name} · ${size.width} × ${size.height} at ${dpi} DPI · ${fileSize(png.length)}`;
    });
  });
  els.downloadSvg.addEventListener('click', () => {
    const settings = pictureSettings(els, 'SVG');
    if (!settings.ok) {
      showExportStatus(els.exportStatus, 'error', settings.message);
      return;
    }
    const { size, dpi, lineWidth, background } = settings;
    const svg: SvgLook = {
      background: background === 'view' ? view.backgroundHex() : background === 'white' ? 'white' : 'none',
      // Lines of one width as the view draws them in the Lines mode; tubes keep the model's widths.
      lineWidth: view.usesLines ? lineWidth : undefined,
      width: size.width,
      height: size.height,
      dpi,
    };
    void downloadModel('svg', 'SVG drawing', { svg });
  });
}

/**
 * The movie's entry, after the model formats: it opens the movie dialog (./movie/, loaded on
 * first use with its encoders).
 */
function installMovie(els: DownloadMenuElements, { view, shown, studio }: { view: PlantView; shown: () => DownloadedPlant | undefined; studio: MovieStudio }): void {
  const button = document.createElement('button');
  button.type = 'button';
  button.className = 'menu-item';
  button.dataset.testid = 'download-movie';
  button.setAttribute('aria-haspopup', 'dialog');
  button.title = 'The growth, or the plant turning, as a video, an animated GIF or numbered PNGs';
  button.append('Movie of the growth…', Object.assign(document.createElement('span'), { className: 'file-type', textContent: '.webm .gif .png' }));
  let dialog: Promise<{ open(): Promise<void> }> | undefined;
  button.addEventListener('click', () => {
    if (!shown()) return;
    els.menu.open = false;
    dialog ??= import('./movie/movie-dialog').then(({ MovieDialog }) => new MovieDialog({ view, name: () => shown()?.name, studio: movieStudio(view, studio) }));
    dialog
      .then((d) => d.open())
      .catch((error: unknown) => {
        dialog = undefined; // (try again: the network may be back)
        showExportStatus(els.exportStatus, 'error', `The movie dialog could not load: ${error instanceof Error ? error.message : String(error)}`);
      });
  });
  const heading = Object.assign(document.createElement('p'), { className: 'menu-heading', textContent: 'Movie of the plant on screen' });
  const items = Object.assign(document.createElement('div'), { className: 'menu-items' });
  items.append(button);
  els.modelDownloads.after(heading, items);
}

/** The studio's timeline and builds, which a movie of a plant derived at t poses the plant through. */
export interface MovieStudio {
  timeline: DerivedStudio['timeline'];
  preview: DerivedStudio['preview'];
}

/** What the movie dialog needs of the studio to film a plant derived at t. */
function movieStudio(view: PlantView, { timeline, preview }: MovieStudio): DerivedStudio {
  return {
    timeline,
    preview,
    uploading: () => view.uploading,
    nextPlantShown: () =>
      new Promise((resolve) => {
        const stop = view.onPlantShown(() => {
          stop();
          resolve();
        });
      }),
  };
}

/** The picture settings read, or the reason they do not make a picture. */
type PictureSettings =
  | { ok: true; size: { width: number; height: number }; dpi: number; lineWidth: number; background: PictureLook['background'] }
  | { ok: false; message: string };

/** Reads the picture settings for a `what` (PNG or SVG) at most `maxSide` pixels on a side. */
function pictureSettings(els: DownloadMenuElements, what: string, maxSide?: number): PictureSettings {
  const size = pictureSize(els.pngWidth.value, els.pngHeight.value, maxSide, what);
  if (!size.ok) return size;
  const lineWidth = Number(els.pngLineWidth.value);
  if (!(lineWidth >= 0.5 && lineWidth <= 60)) return { ok: false, message: `${what} lines: the width must be from 0.5 to 60 pixels` };
  const background = els.pngBackground.value as PictureLook['background'];
  return { ok: true, size: { width: size.width, height: size.height }, dpi: Number(els.pngDpi.value), lineWidth, background };
}

/** A paper (with the DPI) fills in the picture's size; a size typed by hand makes it Custom. */
function installPictureSize(els: DownloadMenuElements): void {
  const fill = () => {
    if (els.pngPaper.value === '') return;
    const { width, height } = paperPixels(els.pngPaper.value as PaperChoice, Number(els.pngDpi.value));
    els.pngWidth.value = String(width);
    els.pngHeight.value = String(height);
  };
  els.pngPaper.addEventListener('change', fill);
  els.pngDpi.addEventListener('change', fill);
  for (const input of [els.pngWidth, els.pngHeight]) input.addEventListener('input', () => (els.pngPaper.value = ''));
}
