// The plant's growth as a glTF animation (docs/LANGUAGE.md, "Growth in time"), from the studio's
// export (the real wasm core, what `meristem export --animate` writes): valid by the Khronos
// validator with no error and no warning, and played by three.js (GLTFLoader, AnimationMixer):
// the plant's bounding box grows over the clip and ends as the whole plant's.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { validateBytes } from 'gltf-validator';
import { AnimationMixer, Box3, LoopOnce, Vector3 } from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { beforeAll, describe, expect, it } from 'vitest';
import { exportModel, initIo } from '../../web/src/core';
import { galleryDir, repoRoot } from './tools';

beforeAll(async () => {
  await initIo(readFileSync(join(repoRoot, 'crate/pkg/meristem_bg.wasm')));
});

/**
 * The GLB without its textures: three.js decodes images with the DOM, which Node has not (the
 * validator checks the textures).
 */
function withoutTextures(glb: Uint8Array): ArrayBuffer {
  const view = new DataView(glb.buffer, glb.byteOffset, glb.byteLength);
  const jsonLength = view.getUint32(12, true);
  const json = JSON.parse(new TextDecoder().decode(glb.subarray(20, 20 + jsonLength))) as {
    images?: unknown;
    textures?: unknown;
    samplers?: unknown;
    materials?: { pbrMetallicRoughness: { baseColorTexture?: unknown } }[];
  };
  delete json.images;
  delete json.textures;
  delete json.samplers;
  for (const m of json.materials ?? []) delete m.pbrMetallicRoughness.baseColorTexture;
  const text = JSON.stringify(json);
  const jsonBytes = new TextEncoder().encode(text + ' '.repeat((4 - (text.length % 4)) % 4));
  const bin = glb.subarray(20 + jsonLength);
  const out = new Uint8Array(20 + jsonBytes.length + bin.length);
  const o = new DataView(out.buffer);
  o.setUint32(0, 0x46546c67, true); // glTF
  o.setUint32(4, 2, true);
  o.setUint32(8, out.length, true);
  o.setUint32(12, jsonBytes.length, true);
  o.setUint32(16, 0x4e4f534a, true); // JSON
  out.set(jsonBytes, 20);
  out.set(bin, 20 + jsonBytes.length);
  return out.buffer;
}

const CASES = [
  { example: 'abop-1.24d.lsys', iterations: 4 },
  { example: 'abop-1.25-bush.lsys', iterations: 3 },
];

describe('the growth as a glTF animation', () => {
  for (const { example, iterations } of CASES) {
    it(`${example}, n = ${iterations}: valid, and three.js plays it growing`, async () => {
      const source = readFileSync(join(galleryDir, example), 'utf8');
      const file = exportModel(source, 'glb', { iterations, animate: true, targetsPerStep: 4, secondsPerStep: 0.5 });
      const report = await validateBytes(file.bytes);
      expect(report.issues.messages).toEqual([]);
      expect(report.issues.numErrors + report.issues.numWarnings).toBe(0);

      const gltf = await new GLTFLoader().parseAsync(withoutTextures(file.bytes), '');
      expect(gltf.animations.map((a) => a.name)).toEqual(['growth']);
      const [clip] = gltf.animations;
      expect(clip.duration).toBeCloseTo(0.5 * iterations, 5);
      const mixer = new AnimationMixer(gltf.scene);
      const action = mixer.clipAction(clip);
      action.setLoop(LoopOnce, 1);
      action.clampWhenFinished = true;
      action.play();
      const sizeAt = (seconds: number): Vector3 => {
        mixer.setTime(seconds);
        gltf.scene.updateMatrixWorld(true);
        return new Box3().setFromObject(gltf.scene, true).getSize(new Vector3());
      };
      const sizes = [0, 1, 2, 3, 4, 5, 6, 7].map((k) => sizeAt((k / 8) * clip.duration));
      for (let k = 1; k < sizes.length; k++) expect(sizes[k].y).toBeGreaterThanOrEqual(sizes[k - 1].y - 1e-4);
      const whole = exportModel(source, 'glb', { iterations });
      const still = await new GLTFLoader().parseAsync(withoutTextures(whole.bytes), '');
      const full = new Box3().setFromObject(still.scene, true).getSize(new Vector3());
      expect(sizes[0].y).toBeLessThan(0.5 * full.y);
      const end = sizeAt(clip.duration);
      expect(end.y).toBeCloseTo(full.y, 3);
      expect(end.x).toBeCloseTo(full.x, 3);
    });
  }

  it('says what to change when the morph targets would be too big', () => {
    const source = readFileSync(join(galleryDir, 'abop-1.24d.lsys'), 'utf8');
    expect(() => exportModel(source, 'glb', { iterations: 7, animate: true, targetsPerStep: 16, sides: 64 })).toThrow(/fewer targets per step/);
    expect(() => exportModel(source, 'obj', { iterations: 2, animate: true })).toThrow(/glTF only/);
  });
});
