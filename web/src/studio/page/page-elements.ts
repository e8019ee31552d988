// The studio page's fixed elements (see index.html), looked up once at the start, grouped by the
// piece of the studio that uses them.

/** The element `#id`, which must be a `type`; a page without it is a broken build. */
export function byId<T extends HTMLElement>(id: string, type: new () => T): T {
  const element = document.getElementById(id);
  if (!(element instanceof type)) throw new Error(`index.html lacks #${id}`);
  return element;
}

/** Looks up the page's fixed elements. */
export function studioElements() {
  return { ...pageFrame(), ...controlElements(), ...inspectorElements(), ...fileElements(), ...outElements() };
}

/** The page's frame: the editor, the view, the status line, the notice, the splitter. */
function pageFrame() {
  return {
    studio: byId('studio', HTMLElement),
    editor: byId('editor', HTMLElement),
    viewport: byId('viewport', HTMLElement),
    variants: byId('variants-toggle', HTMLButtonElement),
    status: byId('status', HTMLElement),
    stopBuild: byId('build-stop', HTMLButtonElement),
    showProblems: byId('show-problems', HTMLButtonElement),
    version: byId('core-version', HTMLElement),
    staleBadge: byId('stale-badge', HTMLElement),
    inspectorStale: byId('inspector-stale', HTMLElement),
    notice: {
      root: byId('notice', HTMLElement),
      text: byId('notice-text', HTMLElement),
      list: byId('notice-list', HTMLElement),
      close: byId('notice-close', HTMLButtonElement),
    },
    splitter: byId('splitter', HTMLElement),
    shortcutList: byId('shortcut-list', HTMLElement),
  };
}

/** The controls around the editor and the view. */
function controlElements() {
  return {
    derivation: {
      iterations: byId('iterations', HTMLInputElement),
      iterationsBox: byId('iterations-box', HTMLElement),
      iterationsTag: byId('iterations-tag', HTMLElement),
      iterationsReset: byId('iterations-reset', HTMLButtonElement),
      stepBack: byId('step-back', HTMLButtonElement),
      stepForward: byId('step-forward', HTMLButtonElement),
      seed: byId('seed', HTMLInputElement),
      reroll: byId('reroll', HTMLButtonElement),
    },
    viewTools: {
      sides: byId('sides', HTMLSelectElement),
      smoothAll: byId('smooth-all', HTMLInputElement),
      frame: byId('frame', HTMLButtonElement),
      projection: byId('projection', HTMLButtonElement),
      renderLines: byId('render-lines', HTMLButtonElement),
      lineWidth: byId('line-width', HTMLInputElement),
      grid: byId('grid', HTMLButtonElement),
      lighting: byId('lighting', HTMLButtonElement),
      textures: byId('textures', HTMLButtonElement),
      byProduction: byId('by-production', HTMLInputElement),
      menus: [byId('tubes-menu', HTMLDetailsElement), byId('lines-menu', HTMLDetailsElement)],
      plantOnly: [...document.querySelectorAll<HTMLElement>('.view-tools .plant-only')],
    },
    layout: {
      paneToggle: byId('pane-toggle', HTMLButtonElement),
      fullscreen: byId('fullscreen', HTMLButtonElement),
      exitViewOnly: byId('exit-view-only', HTMLButtonElement),
      large: byId('large', HTMLButtonElement),
      inspector: byId('inspector', HTMLElement),
      inspectorToggle: byId('inspector-toggle', HTMLButtonElement),
    },
    stages: {
      toggle: byId('stages-toggle', HTMLButtonElement),
      panel: byId('stages', HTMLElement),
      figure: byId('stages-figure', HTMLElement),
      from: byId('stages-from', HTMLInputElement),
      to: byId('stages-to', HTMLInputElement),
      seeds: byId('stages-seeds', HTMLInputElement),
      scale: byId('stages-scale', HTMLSelectElement),
      status: byId('stages-status', HTMLElement),
      png: byId('stages-png', HTMLButtonElement),
      svg: byId('stages-svg', HTMLButtonElement),
    },
    following: {
      refit: byId('refit', HTMLButtonElement),
    },
    timeline: {
      bar: byId('timeline', HTMLElement),
      play: byId('play', HTMLButtonElement),
    },
    sliders: byId('sliders', HTMLElement),
    constantsCount: byId('constants-count', HTMLElement),
    constantsEmpty: byId('constants-empty', HTMLElement),
    growthRows: byId('growth-rows', HTMLElement),
    growthCount: byId('growth-count', HTMLElement),
  };
}

/** The inspector (the String and Derivation tabs) and branch editing. */
function inspectorElements() {
  return {
    contexts: {
      panel: byId('string-panel', HTMLElement),
      summary: byId('explain-summary', HTMLElement),
      legend: byId('production-legend', HTMLElement),
      highlightLegend: byId('highlight-legend', HTMLElement),
    },
    inspectorTabs: [byId('tab-string', HTMLButtonElement), byId('tab-derivation', HTMLButtonElement)],
    derivationPanel: byId('derivation-panel', HTMLElement),
    branchEditing: {
      toggle: byId('edit-branches', HTMLButtonElement),
      undo: byId('edit-undo', HTMLButtonElement),
      redo: byId('edit-redo', HTMLButtonElement),
      reset: byId('edit-reset', HTMLButtonElement),
    },
  };
}

/** Opening and keeping texts: the gallery, My grammars, the File menu, the questions asked before replacing. */
function fileElements() {
  return {
    openGallery: byId('open-gallery', HTMLButtonElement),
    gallery: byId('gallery', HTMLDialogElement),
    galleryList: byId('gallery-list', HTMLElement),
    cannotKeep: {
      dialog: byId('cannot-keep', HTMLDialogElement),
      example: byId('cannot-keep-what', HTMLElement),
    },
    confirm: {
      dialog: byId('confirm-replace', HTMLDialogElement),
      example: byId('confirm-example', HTMLElement),
    },
    fileMenu: {
      menu: byId('file-menu', HTMLDetailsElement),
      openFile: byId('open-file', HTMLButtonElement),
      saveFile: byId('save-file', HTMLButtonElement),
      openLibrary: byId('open-library', HTMLButtonElement),
      fileInput: byId('file-input', HTMLInputElement),
    },
    library: {
      dialog: byId('library', HTMLDialogElement),
      name: byId('library-name', HTMLInputElement),
      save: byId('library-save', HTMLButtonElement),
      list: byId('library-list', HTMLElement),
      empty: byId('library-empty', HTMLElement),
      status: byId('library-status', HTMLElement),
    },
  };
}

/** What goes out: downloads, the Share button and dialog, embed snippets; and the Help panel. */
function outElements() {
  return {
    downloads: {
      menu: byId('downloads', HTMLDetailsElement),
      modelDownloads: byId('model-downloads', HTMLElement),
      pngWidth: byId('png-width', HTMLInputElement),
      pngHeight: byId('png-height', HTMLInputElement),
      downloadPng: byId('download-png', HTMLButtonElement),
      downloadSvg: byId('download-svg', HTMLButtonElement),
      pngPaper: byId('png-paper', HTMLSelectElement),
      pngDpi: byId('png-dpi', HTMLSelectElement),
      pngBackground: byId('png-background', HTMLSelectElement),
      pngLineWidth: byId('png-line-width', HTMLInputElement),
      exportStatus: byId('export-status', HTMLElement),
      exportProgress: byId('export-progress', HTMLProgressElement),
      exportCancel: byId('export-cancel', HTMLButtonElement),
    },
    share: byId('share', HTMLButtonElement),
    shareDialog: {
      dialog: byId('share-dialog', HTMLDialogElement),
      link: byId('share-link', HTMLInputElement),
      copy: byId('share-copy', HTMLButtonElement),
      status: byId('share-status', HTMLElement),
      size: byId('share-size', HTMLElement),
      linkRow: byId('share-row', HTMLElement),
      statusLine: byId('share-status-line', HTMLElement),
      tooLong: byId('share-too-long', HTMLElement),
      tooLongText: byId('share-too-long-text', HTMLElement),
      download: byId('share-download', HTMLButtonElement),
    },
    embedSnippets: {
      iterations: byId('embed-iterations', HTMLInputElement),
      sliders: byId('embed-sliders', HTMLInputElement),
      frame: byId('embed-frame', HTMLTextAreaElement),
      element: byId('embed-element', HTMLTextAreaElement),
      copyFrame: byId('embed-frame-copy', HTMLButtonElement),
      copyElement: byId('embed-element-copy', HTMLButtonElement),
      status: byId('embed-status', HTMLElement),
    },
    help: {
      opener: byId('open-help', HTMLButtonElement),
      panel: byId('help-panel', HTMLDialogElement),
      content: byId('help-content', HTMLElement),
      close: byId('help-close', HTMLButtonElement),
    },
  };
}

/** The page's fixed elements. */
export type StudioElements = ReturnType<typeof studioElements>;
