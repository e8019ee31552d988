// The environment drawn with the plant (issue 47, "Seeing the environment"): a program's grid (the
// light grid) as a semi-transparent heat-map slice, horizontal or vertical, at a layer the user
// chooses; the obstacles as translucent solids with their edges; the attraction points left as
// dots. Loaded on first use (never part of the first load): the studio's environment tools make it
// for a grammar that declares an environment, and give it each build's environment.
// Only three.js classes the first plant's view already has are used (the geometry is made here):
// a class new to the page would go to three's chunk, which the first load carries.
import {
  BufferAttribute,
  BufferGeometry,
  Color,
  DoubleSide,
  Group,
  LineBasicMaterial,
  LineSegments,
  Mesh,
  MeshBasicMaterial,
  MeshStandardMaterial,
  Vector3,
  type Material,
  type Object3D,
} from 'three';
import type { EnvironmentData, EnvironmentField, EnvironmentSolid } from '../core';

/** How a grid is cut: a horizontal slice (a layer of constant y), a vertical one (constant z), or none. */
export type SliceAxis = 'y' | 'z' | 'none';

/**
 * The heat map's colours, from the value 0 (no light) to 1 (full light), sRGB 0-255: a ramp of
 * rising lightness and no green-brown (the plant's colours), so the slice stays legible over it.
 */
export const HEAT_STOPS: readonly (readonly [number, number, number])[] = [
  [20, 11, 52],
  [110, 22, 126],
  [188, 55, 84],
  [245, 125, 21],
  [252, 255, 164],
];

/** The heat map's colour of `value` in [0, 1] (clamped), sRGB 0-255. */
export function heatColour(value: number): [number, number, number] {
  const v = Math.min(1, Math.max(0, Number.isFinite(value) ? value : 0)) * (HEAT_STOPS.length - 1);
  const i = Math.min(HEAT_STOPS.length - 2, Math.floor(v));
  const t = v - i;
  const [a, b] = [HEAT_STOPS[i], HEAT_STOPS[i + 1]];
  return [0, 1, 2].map((c) => Math.round(a[c] + (b[c] - a[c]) * t)) as [number, number, number];
}

/** The values the heat map's colours span: the grid's smallest to largest (a span of 1 when they are equal). */
export function heatRange(field: Pick<EnvironmentField, 'min' | 'max'>): [number, number] {
  return [field.min, field.max > field.min ? field.max : field.min + 1];
}

/** The slice's opacity: the plant shows through it. */
const SLICE_OPACITY = 0.7;
const SOLID_COLOUR = new Color(0x4f7fbf);
const POINT_COLOUR = new Color(0x1d9bd8);

/** How many layers `field` has along `axis` (0 for none). */
export function layersOf(field: EnvironmentField | undefined, axis: SliceAxis): number {
  if (!field || axis === 'none') return 0;
  return axis === 'y' ? field.dims[1] : field.dims[2];
}

/**
 * The layer of `field` along `axis` with the most spread of values (where the grid shows most: the
 * shade of the crown), the first such; 0 for an empty grid.
 */
export function liveliestLayer(field: EnvironmentField, axis: Exclude<SliceAxis, 'none'>): number {
  let best = 0;
  let bestSpread = -1;
  for (let layer = 0; layer < layersOf(field, axis); layer++) {
    let sum = 0;
    let squares = 0;
    let n = 0;
    forEachInSlice(field, axis, layer, (value) => {
      sum += value;
      squares += value * value;
      n++;
    });
    const spread = n > 0 ? squares / n - (sum / n) ** 2 : 0;
    if (spread > bestSpread + 1e-9) [best, bestSpread] = [layer, spread];
  }
  return best;
}

/** Calls `visit(value, u, v)` for each voxel of `layer`: u along x, v along z (a horizontal slice) or y. */
function forEachInSlice(field: EnvironmentField, axis: Exclude<SliceAxis, 'none'>, layer: number, visit: (value: number, u: number, v: number) => void): void {
  const [nx, ny, nz] = field.dims;
  const rows = axis === 'y' ? nz : ny;
  for (let v = 0; v < rows; v++) {
    for (let u = 0; u < nx; u++) {
      const index = axis === 'y' ? u + nx * (layer + ny * v) : u + nx * (v + ny * layer);
      visit(field.values[index] ?? 0, u, v);
    }
  }
}

/** The environment's objects in the scene: one group, made again for each build's environment. */
export class EnvironmentLayer {
  readonly group = new Group();
  private readonly slice = new Group();
  private readonly rest = new Group();
  private field: EnvironmentField | undefined;
  private axis: SliceAxis = 'y';
  private layer = 0;

  constructor() {
    this.group.name = 'environment';
    this.group.add(this.slice, this.rest);
  }

  /** Draws `environment` (its first grid sliced as last chosen, clamped to its layers). */
  show(environment: EnvironmentData | undefined): void {
    clear(this.rest);
    this.field = environment?.fields[0];
    if (environment) {
      for (const solid of environment.solids) this.rest.add(solidObject(solid, this.field));
      if (environment.points.length >= 3) this.rest.add(pointsObject(environment.points));
    }
    this.setSlice(this.axis, this.layer);
  }

  /** The grid sliced (the first program's that keeps one), if any. */
  get sliced(): EnvironmentField | undefined {
    return this.field;
  }

  /** The slice along `axis` at `layer` (clamped to the grid's layers). */
  setSlice(axis: SliceAxis, layer: number): void {
    this.axis = axis;
    const field = this.field;
    const layers = layersOf(field, axis);
    this.layer = Math.max(0, Math.min(layers - 1, Math.round(layer)));
    clear(this.slice);
    if (!field || axis === 'none' || layers === 0) return;
    this.slice.add(sliceMesh(field, axis, this.layer));
  }

  /** The layer shown now. */
  get layerShown(): number {
    return this.layer;
  }

  dispose(): void {
    clear(this.slice);
    clear(this.rest);
  }
}

/** Removes and disposes of every object of `group`. */
function clear(group: Group): void {
  for (const child of [...group.children]) {
    group.remove(child);
    child.traverse((object: Object3D) => {
      const drawn = object as Partial<Mesh>;
      drawn.geometry?.dispose();
      const material = drawn.material as Material | Material[] | undefined;
      for (const m of Array.isArray(material) ? material : material ? [material] : []) m.dispose();
    });
  }
}

/** Most quads a slice is drawn with: a larger layer is drawn a block of voxels a quad. */
const MOST_QUADS = 256 * 256;

/** An sRGB channel (0-255) in linear light, as three.js takes vertex colours. */
function linear(c: number): number {
  const v = c / 255;
  return v <= 0.04045 ? v / 12.92 : ((v + 0.055) / 1.055) ** 2.4;
}

/** A geometry of `positions` (x, y, z each), `indices` and, when given, vertex `colors`. */
function geometryOf(positions: number[] | Float32Array, indices: number[] | Uint32Array | null, colors?: Float32Array): BufferGeometry {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(positions instanceof Float32Array ? positions : new Float32Array(positions), 3));
  if (colors) geometry.setAttribute('color', new BufferAttribute(colors, 3));
  if (indices) geometry.setIndex(new BufferAttribute(indices instanceof Uint32Array ? indices : new Uint32Array(indices), 1));
  return geometry;
}

/** The heat-map slice of one layer of `field`: a flat-coloured quad a voxel (or a block of them). */
function sliceMesh(field: EnvironmentField, axis: Exclude<SliceAxis, 'none'>, layer: number): Mesh {
  const [nx, ny, nz] = field.dims;
  const rows = axis === 'y' ? nz : ny;
  const step = Math.max(1, Math.ceil(Math.sqrt((nx * rows) / MOST_QUADS)));
  const [cols, lines] = [Math.ceil(nx / step), Math.ceil(rows / step)];
  const positions = new Float32Array(cols * lines * 12);
  const colors = new Float32Array(cols * lines * 12);
  const indices = new Uint32Array(cols * lines * 6);
  // The colours spread over the grid's own range (the legend gives its numbers): a plant that
  // shades little still shows where.
  const [lo, hi] = heatRange(field);
  const { origin, cell } = field;
  const depth = (axis === 'y' ? origin[1] : origin[2]) + (layer + 0.5) * cell;
  let quad = 0;
  forEachInSlice(field, axis, layer, (value, u, v) => {
    if (u % step !== 0 || v % step !== 0) return;
    const rgb = heatColour((value - lo) / (hi - lo)).map(linear);
    const x0 = origin[0] + u * cell;
    const x1 = origin[0] + Math.min(u + step, nx) * cell;
    const w0 = (axis === 'y' ? origin[2] : origin[1]) + v * cell;
    const w1 = (axis === 'y' ? origin[2] : origin[1]) + Math.min(v + step, rows) * cell;
    const corners = axis === 'y' ? [x0, depth, w0, x1, depth, w0, x1, depth, w1, x0, depth, w1] : [x0, w0, depth, x1, w0, depth, x1, w1, depth, x0, w1, depth];
    positions.set(corners, quad * 12);
    for (let c = 0; c < 4; c++) colors.set(rgb, quad * 12 + c * 3);
    const first = quad * 4;
    indices.set([first, first + 1, first + 2, first, first + 2, first + 3], quad * 6);
    quad++;
  });
  const material = new MeshBasicMaterial({ vertexColors: true, transparent: true, opacity: SLICE_OPACITY, side: DoubleSide, depthWrite: false, toneMapped: false });
  const mesh = new Mesh(geometryOf(positions.subarray(0, quad * 12), indices.subarray(0, quad * 6), colors.subarray(0, quad * 12)), material);
  mesh.name = 'environment-slice';
  mesh.renderOrder = 2; // after the plant: blended over it
  return mesh;
}

/** A box's corners and triangles, and its 12 edges, from `min` to `max`. */
function boxGeometry(min: Vector3, max: Vector3): { faces: BufferGeometry; edges: BufferGeometry } {
  const corner = (k: number) => [k & 1 ? max.x : min.x, k & 2 ? max.y : min.y, k & 4 ? max.z : min.z];
  const positions = [0, 1, 2, 3, 4, 5, 6, 7].flatMap(corner);
  // Two triangles a side: -x, +x, -y, +y, -z, +z.
  const sides = [[0, 2, 6, 4], [1, 5, 7, 3], [0, 4, 5, 1], [2, 3, 7, 6], [0, 1, 3, 2], [4, 6, 7, 5]];
  const faces = sides.flatMap(([a, b, c, d]) => [a, b, c, a, c, d]);
  const edges = [0, 1, 2, 3, 4, 5, 6, 7].flatMap((k) => [1, 2, 4].filter((bit) => !(k & bit)).flatMap((bit) => [...corner(k), ...corner(k | bit)]));
  return { faces: geometryOf(positions, faces), edges: geometryOf(edges, null) };
}

/** A sphere of `radius` about the origin (32 × 16 quads), and three great circles as its outline. */
function sphereGeometry(radius: number): { faces: BufferGeometry; edges: BufferGeometry } {
  const [around, up] = [32, 16];
  const positions: number[] = [];
  for (let j = 0; j <= up; j++) {
    const theta = (j / up) * Math.PI;
    for (let i = 0; i <= around; i++) {
      const phi = (i / around) * 2 * Math.PI;
      positions.push(radius * Math.sin(theta) * Math.cos(phi), radius * Math.cos(theta), radius * Math.sin(theta) * Math.sin(phi));
    }
  }
  const faces: number[] = [];
  for (let j = 0; j < up; j++)
    for (let i = 0; i < around; i++) {
      const a = j * (around + 1) + i;
      const b = a + around + 1;
      faces.push(a, b, a + 1, b, b + 1, a + 1);
    }
  const edges: number[] = [];
  for (let i = 0; i < around; i++) {
    const [p, q] = [(i / around) * 2 * Math.PI, ((i + 1) / around) * 2 * Math.PI];
    const [cp, sp, cq, sq] = [Math.cos(p), Math.sin(p), Math.cos(q), Math.sin(q)].map((t) => t * radius);
    edges.push(cp, 0, sp, cq, 0, sq, cp, sp, 0, cq, sq, 0, 0, cp, sp, 0, cq, sq);
  }
  return { faces: geometryOf(positions, faces), edges: geometryOf(edges, null) };
}

/** A translucent solid with its edges; a plane as a square about the grid's size (or 20 units). */
function solidObject(solid: EnvironmentSolid, field: EnvironmentField | undefined): Object3D {
  const group = new Group();
  let shape: { faces: BufferGeometry; edges: BufferGeometry };
  if (solid.shape === 'box') {
    shape = boxGeometry(new Vector3(...solid.min), new Vector3(...solid.max));
  } else if (solid.shape === 'sphere') {
    shape = sphereGeometry(solid.radius);
    group.position.set(...solid.center);
  } else {
    const h = field ? Math.max(field.dims[0], field.dims[2]) * field.cell : 10;
    shape = boxGeometry(new Vector3(-h, -h, 0), new Vector3(h, h, 0)); // a square in z = 0, seen from both sides
    group.position.set(...solid.point);
    group.quaternion.setFromUnitVectors(new Vector3(0, 0, 1), new Vector3(...solid.normal).normalize());
  }
  const material = new MeshStandardMaterial({ color: SOLID_COLOUR, transparent: true, opacity: 0.28, side: DoubleSide, depthWrite: false, roughness: 0.8 });
  shape.faces.computeVertexNormals();
  const body = new Mesh(shape.faces, material);
  body.renderOrder = 1;
  const edges = new LineSegments(shape.edges, new LineBasicMaterial({ color: SOLID_COLOUR, transparent: true, opacity: 0.8 }));
  group.add(body, edges);
  group.name = `environment-${solid.shape}`;
  return group;
}

/** The attraction points as small crosses (three short lines each), a 150th of their spread wide. */
function pointsObject(coordinates: Float32Array): LineSegments {
  const lo = new Vector3(Infinity, Infinity, Infinity);
  const hi = new Vector3(-Infinity, -Infinity, -Infinity);
  const p = new Vector3();
  for (let i = 0; i + 2 < coordinates.length; i += 3) {
    p.fromArray(coordinates, i);
    lo.min(p);
    hi.max(p);
  }
  const h = Math.max(hi.distanceTo(lo) / 300, 1e-3);
  const n = Math.floor(coordinates.length / 3);
  const ends = new Float32Array(n * 18);
  for (let k = 0; k < n; k++) {
    const [x, y, z] = [coordinates[3 * k], coordinates[3 * k + 1], coordinates[3 * k + 2]];
    ends.set([x - h, y, z, x + h, y, z, x, y - h, z, x, y + h, z, x, y, z - h, x, y, z + h], k * 18);
  }
  const points = new LineSegments(geometryOf(ends, null), new LineBasicMaterial({ color: POINT_COLOUR }));
  points.name = 'environment-points';
  return points;
}
