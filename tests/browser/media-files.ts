// Reading the movies the studio writes, by their specifications and not by the code that wrote
// them: a WebM's frames (Matroska's EBML elements: the track's pixel size, the blocks of its
// clusters) and an animated GIF's (GIF89a's blocks: the screen's size, each image and its delay).

/** A WebM's video track: its size, codec, duration and the frames of its blocks in order. */
export interface WebmVideo {
  width: number;
  height: number;
  codec: string;
  /** Seconds, from the segment's Duration and TimecodeScale. */
  duration: number;
  blocks: { keyframe: boolean; time: number; data: Uint8Array }[];
}

/** A variable-length integer at `at`: its value (the length marker removed unless `keepMarker`) and its length. */
function vint(bytes: Uint8Array, at: number, keepMarker: boolean): { value: number; length: number; unknown: boolean } {
  const first = bytes[at];
  let length = 1;
  while (length <= 8 && !(first & (0x80 >> (length - 1)))) length++;
  if (length > 8) throw new Error(`bad EBML number at ${at}`);
  let value = keepMarker ? first : first & (0xff >> length);
  let allOnes = value === (0xff >> length);
  for (let i = 1; i < length; i++) {
    value = value * 256 + bytes[at + i];
    allOnes &&= bytes[at + i] === 0xff;
  }
  return { value, length, unknown: !keepMarker && allOnes };
}

const MASTERS = new Set([0x18538067 /* Segment */, 0x1f43b675 /* Cluster */, 0x1654ae6b /* Tracks */, 0xae /* TrackEntry */, 0xe0 /* Video */, 0x1549a966 /* Info */, 0xa0 /* BlockGroup */]);

function unsigned(bytes: Uint8Array): number {
  return bytes.reduce((n, b) => n * 256 + b, 0);
}

/** Reads a WebM file's first video track and its blocks (SimpleBlocks and Blocks of block groups). */
export function readWebm(bytes: Uint8Array): WebmVideo {
  const video: WebmVideo = { width: 0, height: 0, codec: '', duration: 0, blocks: [] };
  let clusterTime = 0;
  let scale = 1_000_000;
  let rawDuration = 0;
  const walk = (start: number, end: number) => {
    for (let at = start; at < end; ) {
      const id = vint(bytes, at, true);
      const size = vint(bytes, at + id.length, false);
      const body = at + id.length + size.length;
      const bodyEnd = size.unknown ? end : body + size.value;
      const data = bytes.subarray(body, bodyEnd);
      if (MASTERS.has(id.value)) walk(body, bodyEnd);
      else if (id.value === 0xb0) video.width = unsigned(data);
      else if (id.value === 0xba) video.height = unsigned(data);
      else if (id.value === 0x86) video.codec = new TextDecoder().decode(data);
      else if (id.value === 0x2ad7b1) scale = unsigned(data);
      else if (id.value === 0x4489) rawDuration = data.length === 4 ? new DataView(data.buffer, data.byteOffset).getFloat32(0) : new DataView(data.buffer, data.byteOffset).getFloat64(0);
      else if (id.value === 0xe7) clusterTime = unsigned(data);
      else if (id.value === 0xa3 || id.value === 0xa1) {
        const track = vint(data, 0, false);
        const view = new DataView(data.buffer, data.byteOffset + track.length);
        const time = clusterTime + view.getInt16(0);
        const keyframe = id.value === 0xa3 ? (view.getUint8(2) & 0x80) !== 0 : video.blocks.length === 0;
        video.blocks.push({ keyframe, time: (time * scale) / 1e9, data: data.subarray(track.length + 3) });
      }
      at = bodyEnd;
    }
  };
  walk(0, bytes.length);
  video.duration = (rawDuration * scale) / 1e9;
  return video;
}

/** An animated GIF: its logical screen, and each image's size and delay (hundredths of a second). */
export interface GifAnimation {
  width: number;
  height: number;
  /** The NETSCAPE2.0 loop count (0: forever), or null without one. */
  loops: number | null;
  frames: { width: number; height: number; delay: number }[];
}

/** Reads a GIF89a's blocks. */
export function readGif(bytes: Uint8Array): GifAnimation {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const signature = new TextDecoder().decode(bytes.subarray(0, 6));
  if (signature !== 'GIF89a') throw new Error(`not a GIF89a: ${signature}`);
  const gif: GifAnimation = { width: view.getUint16(6, true), height: view.getUint16(8, true), loops: null, frames: [] };
  const tableSize = (packed: number) => (packed & 0x80 ? 3 * 2 ** ((packed & 7) + 1) : 0);
  let at = 13 + tableSize(bytes[10]);
  let delay = 0;
  /** Skips data sub-blocks from `from`; returns the first of them and the index after the terminator. */
  const subBlocks = (from: number) => {
    const first = bytes.subarray(from + 1, from + 1 + bytes[from]);
    let i = from;
    while (bytes[i] !== 0) i += bytes[i] + 1;
    return { first, next: i + 1 };
  };
  for (;;) {
    const kind = bytes[at];
    if (kind === 0x3b) return gif; // trailer
    if (kind === 0x21) {
      const label = bytes[at + 1];
      const { first, next } = subBlocks(at + 2);
      if (label === 0xf9) delay = first[1] | (first[2] << 8);
      if (label === 0xff && new TextDecoder().decode(first) === 'NETSCAPE2.0') gif.loops = bytes[at + 2 + 1 + 11 + 2] | (bytes[at + 2 + 1 + 11 + 3] << 8);
      at = next;
    } else if (kind === 0x2c) {
      gif.frames.push({ width: view.getUint16(at + 5, true), height: view.getUint16(at + 7, true), delay });
      at += 10 + tableSize(bytes[at + 9]) + 1; // descriptor, local table, LZW minimum code size
      at = subBlocks(at).next;
    } else throw new Error(`unexpected GIF block 0x${kind?.toString(16)} at ${at}`);
  }
}

/** An MP4's first video track: its size (the track header's) and its number of samples (frames). */
export interface Mp4Video {
  width: number;
  height: number;
  /** The sample description's format: `avc1` for H.264. */
  format: string;
  samples: number;
}

/** Reads an MP4 (ISO BMFF) file's first track: moov ▸ trak ▸ tkhd, and mdia ▸ minf ▸ stbl ▸ stsd, stsz. */
export function readMp4(bytes: Uint8Array): Mp4Video {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const video: Mp4Video = { width: 0, height: 0, format: '', samples: 0 };
  const containers = new Set(['moov', 'trak', 'mdia', 'minf', 'stbl']);
  let tracks = 0;
  const walk = (start: number, end: number) => {
    for (let at = start; at + 8 <= end; ) {
      const size = view.getUint32(at);
      const type = new TextDecoder().decode(bytes.subarray(at + 4, at + 8));
      const boxEnd = size === 0 ? end : at + size;
      if (type === 'trak' && tracks++ > 0) return; // the first track only
      if (containers.has(type)) walk(at + 8, boxEnd);
      else if (type === 'tkhd') {
        const version = bytes[at + 8];
        const fields = at + 8 + (version === 1 ? 84 : 72) + 4; // after the header, its times, the matrix
        [video.width, video.height] = [view.getUint32(fields) / 65536, view.getUint32(fields + 4) / 65536];
      } else if (type === 'stsd') video.format = new TextDecoder().decode(bytes.subarray(at + 20, at + 24));
      else if (type === 'stsz') video.samples = view.getUint32(at + 16);
      at = boxEnd;
    }
  };
  walk(0, bytes.length);
  return video;
}
