// Types of the parts of the Khronos glTF validator (npm `gltf-validator`) the export tests use.
declare module 'gltf-validator' {
  /** One problem the validator found. */
  export interface ValidationMessage {
    code: string;
    message: string;
    /** 0 error, 1 warning, 2 information, 3 hint. */
    severity: number;
    pointer?: string;
    offset?: number;
  }

  /** The validation report (`validation.schema.json`). */
  export interface ValidationReport {
    issues: {
      numErrors: number;
      numWarnings: number;
      numInfos: number;
      numHints: number;
      messages: ValidationMessage[];
      truncated: boolean;
    };
    info?: {
      version?: string;
      generator?: string;
      drawCallCount?: number;
      totalVertexCount?: number;
      totalTriangleCount?: number;
      materialCount?: number;
    };
  }

  export interface ValidationOptions {
    uri?: string;
    format?: 'glb' | 'gltf';
    maxIssues?: number;
    ignoredIssues?: string[];
  }

  export function validateBytes(data: Uint8Array, options?: ValidationOptions): Promise<ValidationReport>;
  export function version(): string;
}
