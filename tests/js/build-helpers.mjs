// Shared by the scene-building tests: the native CLI's `check` on a scene object, whether
// this core reads version 4 yet, a seeded RNG and the "refused and unchanged" assertion.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { lowestVersion } from '../../web/state/scene-build.js';

const root = new URL('../../', import.meta.url);
export const CLI = process.env.PDESURF_CLI ?? new URL(`${process.env.PDESURF_BUILD_DIR ?? 'build'}/native/pdesurf`, root).pathname;
const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'pdesurf-build-'));
let serial = 0;

/** `pdesurf check` on a scene: { status, report (parsed --json, or null), stderr }. */
export function check(scene, grid = 32) {
  const file = path.join(dir, `scene${serial++}.json`);
  fs.writeFileSync(file, JSON.stringify(scene));
  const r = spawnSync(CLI, ['check', file, '--json', '--grid', `${grid}x${grid}`], { encoding: 'utf8' });
  if (r.error) throw r.error;
  let report = null;
  try { report = JSON.parse(r.stdout); } catch { /* refused: stderr says why */ }
  return { status: r.status, report, stderr: r.stderr.trim() };
}

/**
 * The scene as the core on this build can read it: version 3 when it uses no version-4
 * field and the core reads 1-3 only, else as it is.
 */
export function forCore(scene) {
  const copy = structuredClone(scene);
  if (!V4 && lowestVersion(copy) <= 3) copy.version = 3;
  return copy;
}

// What the core on this build reads: version 4 with a placement; a Bézier patch's borders.
const surface = { name: 's', kind: 'surface', t_range: [0, 1], v_range: [0, 1], x: 't', y: 'v', z: '0' };
const placed = { format: 'pdesurf-scene', version: 4, parameters: {}, patches: [{ ...surface, placement: { translate: [1, 0, 0], rotate: [0, 0, 90], scale: 2 } }] };
const bordered = {
  format: 'pdesurf-scene', version: 4, parameters: {},
  patches: [surface, { name: 'f', kind: 'bezier', energy: 'membrane', degree: [2, 2], normals: { degree: [0, 0], vectors: [[0, 0, 1]] },
    borders: { v0: { surface: 's', at: 't0', reverse: false } },
    control_net: Array.from({ length: 9 }, (_, k) => [Math.floor(k / 3), k % 3, 0]) }],
};
export const V4 = check(placed).status === 0;
export const NO_V4 = V4 ? false : 'the core on this build reads scene versions 1-3 only (placement is version 4, being added in parallel)';
export const NO_BORDERS = check(bordered).status === 0 ? false
  : `the core on this build does not read a Bézier patch's borders yet (version 4, being added in parallel): ${check(bordered).stderr}`;

/** mulberry32: a small seeded RNG, so the random pairs are the same on every run. */
export function rng(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** `edit()` throws an Error whose message matches `pattern`, and `scene` is deep-equal to before. */
export function refuses(scene, edit, pattern) {
  const before = structuredClone(scene);
  assert.throws(edit, (e) => e instanceof Error && pattern.test(e.message), `expected a refusal matching ${pattern}`);
  assert.deepEqual(scene, before, 'a refused edit changes nothing');
}
