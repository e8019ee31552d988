// The growth timeline as a share link (and an embed's attributes) keep it: the growth time, the
// speed, the range and how it plays. Every value comes from a hostile fragment or attribute: each
// is kept only when it has the right type, numbers clamped to their bounds, anything else dropped
// (the link still opens: the timeline then starts as it would without it).

/** The timeline's state in a link; every field optional. */
export interface SharedGrowth {
  /** The growth time shown, in derivation steps. */
  t?: number;
  /** Steps per second. */
  speed?: number;
  /** The range played. */
  from?: number;
  to?: number;
  loop?: boolean;
  /** The camera while it plays: on the final plant, or following the growth. */
  camera?: 'final' | 'follow';
  /** The camera turning about the plant while it plays. */
  turntable?: boolean;
  /** Whether it was playing (an embed's `animate`). */
  playing?: boolean;
}

/** The largest growth time a link may hold (far past any derivation's step limit). */
export const GROWTH_TIME_MAX = 1_000_000;
/** The slowest and fastest speeds a link may hold, in steps per second. */
export const GROWTH_SPEED_MIN = 0.05;
export const GROWTH_SPEED_MAX = 20;

/** A number (or numeric text) clamped to [low, high], or undefined when it is not a finite one. */
function clamped(value: unknown, low: number, high: number): number | undefined {
  const n = typeof value === 'number' ? value : typeof value === 'string' && value.trim() !== '' ? Number(value) : NaN;
  return Number.isFinite(n) ? Math.min(high, Math.max(low, n)) : undefined;
}

/** A boolean, or the text `true`/`false`, or undefined. */
function flag(value: unknown): boolean | undefined {
  if (typeof value === 'boolean') return value;
  return value === 'true' ? true : value === 'false' ? false : undefined;
}

/** The well-formed part of a link's growth state, or undefined when nothing of it is. */
export function cleanGrowth(growth: unknown): SharedGrowth | undefined {
  if (typeof growth !== 'object' || growth === null || Array.isArray(growth)) return undefined;
  const raw = growth as Record<string, unknown>;
  const clean: SharedGrowth = {};
  const t = clamped(raw.t, 0, GROWTH_TIME_MAX);
  if (t !== undefined) clean.t = t;
  const speed = clamped(raw.speed, GROWTH_SPEED_MIN, GROWTH_SPEED_MAX);
  if (speed !== undefined) clean.speed = speed;
  const from = clamped(raw.from, 0, GROWTH_TIME_MAX);
  if (from !== undefined) clean.from = from;
  const to = clamped(raw.to, from ?? 0, GROWTH_TIME_MAX);
  if (to !== undefined) clean.to = to;
  for (const key of ['loop', 'turntable', 'playing'] as const) {
    const value = flag(raw[key]);
    if (value !== undefined) clean[key] = value;
  }
  if (raw.camera === 'final' || raw.camera === 'follow') clean.camera = raw.camera;
  return Object.keys(clean).length > 0 ? clean : undefined;
}
