// Renaming any patch of any example keeps the model (issue 39: the outliner's rename updated a
// blend's surface and a Bézier border's reference, not a chain's patch nor a fill's borders;
// 24 of 150 renames left a scene that no longer solved). Each rename through the page's
// renamePatch, then solved by the module: the same patches, the same points.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import { loadTestSolver } from './test-solver.mjs';
import { renamePatch } from '../../web/state/scene-build.js';
import { dependentsOf } from '../../web/state/patch-delete.js';
import { upstreamOf } from '../../web/ui/outliner.js';

const root = new URL('../../', import.meta.url);
const solver = await loadTestSolver();
const examples = readdirSync(new URL('examples/', root)).filter((f) => f.endsWith('.json') && f !== 'index.json');
const options = { nu: 4, nv: 4 };

test('every patch of every example renamed alone: the model solves to the same points, its references follow', () => {
  let renames = 0, referenced = 0;
  for (const file of examples) {
    const text = readFileSync(new URL(`examples/${file}`, root), 'utf8');
    const before = solver.solve(JSON.parse(text), options).patches;
    for (const { name } of JSON.parse(text).patches) {
      const scene = JSON.parse(text);
      const dependents = dependentsOf(scene, name).map((d) => d.patch);
      renamePatch(scene, name, `${name}_renamed`);
      renames++;
      // Nothing names the old name any more; every dependent now names the new one.
      for (const p of scene.patches) {
        assert.ok(!upstreamOf(p).includes(name), `${file}: ${p.name} still names ${name}`);
        if (dependents.includes(p.name)) referenced++, assert.ok(upstreamOf(p).includes(`${name}_renamed`), `${file}: ${p.name}`);
      }
      let after;
      try {
        after = solver.solve(scene, options).patches;
      } catch (e) {
        assert.fail(`${file}: renaming ${name}: ${e.message}`);
      }
      assert.equal(after.length, before.length, file);
      after.forEach((p, k) => {
        assert.equal(p.name, before[k].name === name ? `${name}_renamed` : before[k].name);
        assert.deepEqual([...p.positions], [...before[k].positions], `${file}: ${p.name} moved when ${name} was renamed`);
      });
    }
  }
  assert.ok(renames > 140, `${renames} renames`);
  assert.ok(referenced > 40, `${referenced} references followed`);
});
