// Shared by the scene-building tests: the native CLI's `check` on a scene object, a seeded
// RNG and the "refused and unchanged" assertion.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { spawnSync } from 'node:child_process';

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
