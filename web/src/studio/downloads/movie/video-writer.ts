// Video through WebCodecs: the browser's VideoEncoder (VP9 for WebM, H.264 for MP4 where the browser
// has an encoder for it) and a muxer (webm-muxer, mp4-muxer) putting its chunks in the file. Loaded
// with the movie dialog, the muxer of the format asked for on first use.
import type { MovieWriter } from './movie-writer';

/** The two video formats. */
export type VideoFormat = 'webm' | 'mp4';

/** The codec string for a video of `width` × `height` in `format`, its level by its size (VP9 3.1, 4.1, 5.1; H.264 High 3.1, 4.0, 5.1). */
export function videoCodec(format: VideoFormat, width: number, height: number): string {
  const pixels = width * height;
  const level = pixels <= 1280 * 720 ? 0 : pixels <= 2048 * 1088 ? 1 : 2;
  return format === 'webm' ? ['vp09.00.31.08', 'vp09.00.41.08', 'vp09.00.51.08'][level] : ['avc1.64001f', 'avc1.640028', 'avc1.640033'][level];
}

/** The encoder's settings: about 0.15 bits a pixel a frame (a plant on a plain background is easy to compress), at least 1 Mbit/s. */
export function videoConfig(format: VideoFormat, width: number, height: number, fps: number): VideoEncoderConfig {
  const bitrate = Math.max(1e6, Math.round(width * height * fps * 0.15));
  return { codec: videoCodec(format, width, height), width, height, bitrate, framerate: fps, latencyMode: 'quality' };
}

/** Whether this browser can encode `format` at `width` × `height` (an MP4 needs an H.264 encoder, which not every browser has). */
export async function canEncode(format: VideoFormat, width: number, height: number, fps: number): Promise<boolean> {
  if (typeof VideoEncoder === 'undefined') return false;
  try {
    return (await VideoEncoder.isConfigSupported(videoConfig(format, width, height, fps))).supported === true;
  } catch {
    return false;
  }
}

/** The muxer of either format: chunks in, the file's bytes out. */
interface Muxer {
  addVideoChunk(chunk: EncodedVideoChunk, meta?: EncodedVideoChunkMetadata): void;
  finalize(): void;
  bytes(): ArrayBuffer;
}

async function muxer(format: VideoFormat, width: number, height: number, fps: number): Promise<Muxer> {
  if (format === 'webm') {
    const { Muxer, ArrayBufferTarget } = await import('webm-muxer');
    const target = new ArrayBufferTarget();
    const muxer = new Muxer({ target, video: { codec: 'V_VP9', width, height, frameRate: fps }, firstTimestampBehavior: 'offset' });
    return { addVideoChunk: (chunk, meta) => muxer.addVideoChunk(chunk, meta), finalize: () => muxer.finalize(), bytes: () => target.buffer };
  }
  const { Muxer, ArrayBufferTarget } = await import('mp4-muxer');
  const target = new ArrayBufferTarget();
  const muxer = new Muxer({ target, video: { codec: 'avc', width, height, frameRate: fps }, fastStart: 'in-memory', firstTimestampBehavior: 'offset' });
  return { addVideoChunk: (chunk, meta) => muxer.addVideoChunk(chunk, meta), finalize: () => muxer.finalize(), bytes: () => target.buffer };
}

/** Frames the encoder may hold before the next is drawn (it encodes while the next frame is drawn). */
const QUEUE = 3;

/** A writer of a `format` video of `width` × `height` at `fps`, a key frame every two seconds (players seek to them). */
export async function videoWriter(format: VideoFormat, width: number, height: number, fps: number): Promise<MovieWriter> {
  const mux = await muxer(format, width, height, fps);
  let failure: Error | undefined;
  const encoder = new VideoEncoder({
    output: (chunk, meta) => mux.addVideoChunk(chunk, meta),
    error: (error) => (failure = new Error(`the video encoder failed: ${error.message}`)),
  });
  encoder.configure(videoConfig(format, width, height, fps));
  const frameMicroseconds = 1e6 / fps;
  const check = () => {
    if (failure) throw failure;
  };
  return {
    add: async (canvas, index) => {
      check();
      const frame = new VideoFrame(canvas, { timestamp: Math.round(index * frameMicroseconds), duration: Math.round(frameMicroseconds) });
      try {
        encoder.encode(frame, { keyFrame: index % (2 * fps) === 0 });
      } finally {
        frame.close(); // the encoder keeps what it needs
      }
      while (encoder.encodeQueueSize > QUEUE && encoder.state === 'configured') {
        await new Promise((resolve) => encoder.addEventListener('dequeue', resolve, { once: true }));
      }
      check();
    },
    finish: async () => {
      await encoder.flush();
      check();
      encoder.close();
      mux.finalize();
      return new Blob([mux.bytes()], { type: format === 'webm' ? 'video/webm' : 'video/mp4' });
    },
    close: () => {
      if (encoder.state !== 'closed') encoder.close();
    },
  };
}
