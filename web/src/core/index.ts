// The core: the Rust/WebAssembly pipeline behind an idiomatic TypeScript facade.
// Invariant: no other TypeScript imports crate/pkg; everything else uses these names.
export { initCore, CoreCrashed } from './init';
export { coreModule, CORE_VERSION } from './compile';
export { initIo } from './io';
export { loadBranchEditing, type EditPlant } from './editing';
export { loadSurfacePreview, type Point3, type SurfaceAnswer, type SurfacePreview, type SurfacePreviewer, type WrittenPoint } from './surfaces';
export { buildPlant, inspectPlant, needsStudioCore, prepareSpares, studioCoreInUse, type InspectRequest, type PlantSketch, type SketchRequest } from './build';
export { loadStudioCore } from './studio-core-loader';
export {
  exportModel,
  exportModelWithProgress,
  MODEL_FORMATS,
  type ExportOptions,
  type ExportProgress,
  type ExportStage,
  type ModelFile,
  type ModelFormat,
  type SvgLook,
} from './export';
export {
  argumentsText,
  directiveOfKind,
  languageVocabulary,
  loadVocabulary,
  onVocabulary,
  useVocabulary,
  vocabularyIfLoaded,
  paramsText,
  writtenDirective,
  writtenKeyword,
  type DirectiveInfo,
  type FunctionInfo,
  type KeywordInfo,
  type ModuleCategory,
  type ModuleInfo,
  type Param,
  type ParamKind,
  type ValueInfo,
  type Vocabulary,
} from './vocabulary';
export { byteOffsetToUtf16, utf16Offsets } from './offsets';
export { columnBuffers, diagnosticList, DiagnosticList, NO_DIAGNOSTICS, type DiagnosticColumns } from './diagnostic-list';
export { importDerived, importGrammar, importObject, pythonRoute, type Dialect, type ImportedGrammar, type ImportNote, type ObjectFile, type PythonRoute } from './import';
export {
  applyMeshUpdate,
  DragRefused,
  noEdits,
  type BranchEdit,
  type BranchInfo,
  type EditReport,
  type EditsDocument,
  type Handle,
  type MeshUpdate,
  type PlantEditor,
  type Vec3,
} from './branches';
export {
  NOT_REWRITTEN,
  type Bounds,
  type ContextCheck,
  type DerivationStep,
  type LastStepLinks,
  type BreakpointAnswer,
  type Lineage,
  type LineageRow,
  type MatchReport,
  type Explanation,
  type PlantInspector,
  type ProductionInfo,
  type BuildOptions,
  type BuildProgress,
  type BuildStage,
  type Diagnostic,
  type EnvironmentData,
  type EnvironmentField,
  type EnvironmentSolid,
  type GpuArrays,
  type MeshBuffers,
  type PlantBuild,
  type PlantStats,
  type Severity,
  type StageTimings,
} from './types';
export { onDemand } from './on-demand';
