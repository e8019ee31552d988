// The facade over the core's file writers: one call, the file's bytes out, the wasm object freed.
import { exportModel as coreExportModel, type ExportedModel, type SvgLook } from '../../../crate/pkg/meristem.js';
import type { EditsDocument } from './branches';
import { guarded } from './init';
import { assertIoReady } from './io';
import type { BuildOptions } from './types';

/** An SVG's picture settings (background, line width, size, DPI): the core's, as `meristem export` takes them. */
export type { SvgLook };

/** A model format the core writes, named by its file extension. */
export type ModelFormat = 'wrl' | 'glb' | 'pov' | 'obj' | 'iv' | 'svg';

/** The formats in menu order, with what a user sees for each (the Download menu puts SVG with the PNG, under the picture settings). */
export const MODEL_FORMATS: readonly { format: ModelFormat; label: string; file: string }[] = [
  { format: 'wrl', label: 'VRML 2.0', file: '.wrl' },
  { format: 'glb', label: 'glTF 2.0 binary', file: '.glb' },
  { format: 'pov', label: 'POV-Ray 3.7 scene + textures', file: '.zip' },
  { format: 'obj', label: 'OBJ + MTL', file: '.zip' },
  { format: 'iv', label: 'OpenInventor 2.1', file: '.iv' },
  { format: 'svg', label: 'SVG drawing (X–Y plane)', file: '.svg' },
];

/** A file ready to download. */
export interface ModelFile {
  /** `plant.glb`, or `plant-obj.zip` (OBJ and its MTL) and `plant-pov.zip` (the scene and its texture images). */
  fileName: string;
  mimeType: string;
  /** The file's bytes, owned by JavaScript. */
  bytes: Uint8Array;
}

/** Options of {@link exportModel}: the build's, and the file name without extension. */
export interface ExportOptions extends BuildOptions {
  /**
   * File name without extension; default `plant` (a zip of several files: `NAME-obj.zip`, `NAME-pov.zip`).
   * The core makes it a safe stem first: at most 64 characters, path separators, control characters
   * and spaces as `-`, no dot or dash at either end (`../../x` gives `x`).
   */
  name?: string;
  /** Branch edits to apply first (the file is then `meristem export … --edits EDITS.json`'s). */
  edits?: EditsDocument;
  /** An SVG's picture settings (the CLI's `--background`, `--line-width`, `--size`, `--dpi`); SVG only. */
  svg?: SvgLook;
  /**
   * glTF only: the plant's growth as a standard glTF animation (morph targets keyed in time, the
   * CLI's `--animate`), `secondsPerStep` (0.001 to 3600, default 1) and `targetsPerStep` (1 to 16, default 4).
   */
  animate?: boolean;
  secondsPerStep?: number;
  targetsPerStep?: number;
}

/**
 * Builds `source` with `options` (as {@link buildPlant} does, so the mesh is the one on screen) and
 * writes its model in `format`: the same bytes as `meristem export FILE -o NAME.EXT` for the same
 * grammar, iterations, seed, sides and smooth axes (for `obj`, a zip holding exactly the command's
 * NAME.obj and NAME.mtl). With `options.edits`, the branch edits are applied first (edits whose
 * branch no longer exists are left out). Throws when the grammar has errors (export only a plant
 * that built), the edits are malformed, or the core fails. Requires {@link initCore}.
 */
export function exportModel(source: string, format: ModelFormat, options: ExportOptions = {}): ModelFile {
  return runExport(source, format, options);
}

/** The core's export options for `format` and `options`. */
function coreOptions(format: ModelFormat, options: ExportOptions) {
  const { iterations, seed, sides, smoothAll, name, edits, svg, animate, secondsPerStep, targetsPerStep } = options;
  return { format, name, iterations, seed, sides, smoothAll, edits: edits ? JSON.stringify(edits) : undefined, svg, animate, secondsPerStep, targetsPerStep };
}

/** Runs the core's export, telling `onProgress` each stage when given. */
function runExport(source: string, format: ModelFormat, options: ExportOptions, onProgress?: (progress: ExportProgress) => void): ModelFile {
  assertIoReady();
  const progress = onProgress && ((stage: ExportStage, index: number, count: number) => onProgress({ stage, index, count }));
  return takeFile(guarded(() => coreExportModel(source, coreOptions(format, options), progress)));
}

/** A stage of an export, as the core reports it (in this order; `applying edits` only with edits). */
export type ExportStage = 'parsing' | 'deriving' | 'interpreting' | 'meshing' | 'applying edits' | 'writing';

/** Where an export is: the stage that just started, its index and the number of stages. */
export interface ExportProgress {
  stage: ExportStage;
  index: number;
  count: number;
}

/**
 * {@link exportModel}, telling `onProgress` each stage as it starts (the core calls it between its
 * stages). The bytes are the same as {@link exportModel}'s. For the export worker.
 */
export function exportModelWithProgress(
  source: string,
  format: ModelFormat,
  options: ExportOptions,
  onProgress: (progress: ExportProgress) => void,
): ModelFile {
  return runExport(source, format, options, onProgress);
}

/** Copies a wasm file out of wasm memory and frees it. */
function takeFile(result: ExportedModel): ModelFile {
  try {
    return guarded(() => ({ fileName: result.fileName, mimeType: result.mimeType, bytes: result.bytes() }));
  } finally {
    result.free();
  }
}
