// Duplicating or deleting any patch of any example through the page's edits (issue 39:
// web/state/scene-build.js duplicatePatch, web/state/patch-delete.js deletePatch): each result
// is a model the module solves, or a refusal by name before the core is asked; the patches the
// edit does not touch keep their points, nothing names a patch that is gone, and a model whose
// joins were certified still certifies (a detached fill's rings are typed from the solved net in
// doubles: rounded to float32 digits, its corners missed the borders still by reference).
//   PDESURF_BUILD_DIR=build node --test tests/js/duplicate-delete-every-patch.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import { loadTestSolver } from './test-solver.mjs';
import { duplicatePatch } from '../../web/state/scene-build.js';
import { deletePatch, dependentsOf } from '../../web/state/patch-delete.js';
import { upstreamOf } from '../../web/ui/outliner.js';

const root = new URL('../../', import.meta.url);
const solver = await loadTestSolver();
const examples = readdirSync(new URL('examples/', root)).filter((f) => f.endsWith('.json') && f !== 'index.json');
const options = { nu: 4, nv: 4 };
const read = (file) => readFileSync(new URL(`examples/${file}`, root), 'utf8');
const byName = (patches) => new Map(patches.map((p) => [p.name, [...p.positions]]));
const certified = (scene) => solver.solve(scene, { ...options, joins: true }).report;
function checkJoins(scene, wasOk, what) {
  if (!wasOk) return 0;
  const report = certified(scene);
  const failing = [...report.joins, ...report.seams].filter((j) => !j.ok).map((j) => `${j.patch}:${j.end} - ${j.surface}:${j.edge}`);
  assert.ok(report.ok, `${what}: the joins no longer certify (${failing.join('; ') || report.error?.message || 'centres or crossings'})`);
  return 1;
}

function solveOrFail(scene, what) {
  try {
    return solver.solve(scene, options).patches;
  } catch (e) {
    assert.fail(`${what}: the edit left a scene the module refuses: ${e.message}`);
  }
}

test('every patch of every example duplicated: solved with the copy where the original is, or refused by name', () => {
  let copies = 0, refused = 0, reports = 0;
  for (const file of examples) {
    const text = read(file);
    const before = byName(solver.solve(JSON.parse(text), options).patches);
    const wasOk = certified(JSON.parse(text)).ok;
    for (const { name } of JSON.parse(text).patches) {
      const scene = JSON.parse(text);
      let copy;
      try {
        copy = duplicatePatch(scene, name);
      } catch (e) {
        // A second blend on the same borders would put three sheets on an edge.
        assert.match(e.message, /already|three sheets|met by/, `${file}: duplicating ${name}: ${e.message}`);
        refused++;
        continue;
      }
      const after = byName(solveOrFail(scene, `${file}: duplicating ${name}`));
      assert.equal(after.size, before.size + 1, `${file}: ${name}`);
      for (const [n, points] of before) assert.deepEqual(after.get(n), points, `${file}: ${n} moved when ${name} was duplicated`);
      assert.deepEqual(after.get(copy), before.get(name), `${file}: the copy of ${name} is not where it is`);
      reports += checkJoins(scene, wasOk, `${file}: duplicating ${name}`);
      copies++;
    }
  }
  assert.ok(copies > 100, `${copies} copies, ${refused} refused`);
  assert.ok(reports > 50, `${reports} reports`);
});

test('every patch of every example deleted with its dependents, and with them detached: the rest solves, unmoved', () => {
  let deletes = 0, detaches = 0, notDetachable = 0, reports = 0;
  for (const file of examples) {
    const text = read(file);
    const solved = solver.solve(JSON.parse(text), options).patches;
    const wasOk = certified(JSON.parse(text)).ok;
    const before = byName(solved);
    for (const { name } of JSON.parse(text).patches) {
      for (const dependents of ['delete', 'detach']) {
        const scene = JSON.parse(text);
        const hasDependents = dependentsOf(scene, name).length > 0;
        if (dependents === 'detach' && !hasDependents) continue;
        let gone;
        try {
          gone = deletePatch(scene, name, { dependents, solved });
        } catch (e) {
          // A chain or a fill's loop cannot be detached, nor an end on a NURBS surface (its
          // border is B-spline data, not text): said by name.
          assert.ok(dependents === 'detach' && /cannot be detached|cannot detach: this end meets a NURBS surface/.test(e.message), `${file}: deleting ${name} (${dependents}): ${e.message}`);
          notDetachable++;
          continue;
        }
        assert.ok(gone.includes(name));
        for (const p of scene.patches) for (const g of gone) assert.ok(!upstreamOf(p).includes(g), `${file}: ${p.name} still names ${g}`);
        if (scene.patches.length === 0) continue;
        const after = byName(solveOrFail(scene, `${file}: deleting ${name} (${dependents})`));
        assert.equal(after.size, before.size - gone.length, `${file}: ${name}`);
        for (const [n, points] of after) {
          // What stays keeps its points; a detached dependent keeps its shape to the float32
          // digits its typed data was written with.
          const was = before.get(n);
          const worst = Math.max(...points.map((x, k) => Math.abs(x - was[k])));
          const scale = Math.max(1, ...was.map(Math.abs));
          assert.ok(worst <= 1e-5 * scale, `${file}: ${n} moved by ${worst} when ${name} was deleted (${dependents})`);
        }
        reports += checkJoins(scene, wasOk, `${file}: deleting ${name} (${dependents})`);
        if (dependents === 'delete') deletes++;
        else detaches++;
      }
    }
  }
  assert.ok(deletes > 120, `${deletes} deletes`);
  assert.ok(reports > 50, `${reports} reports`);
  assert.ok(detaches > 10, `${detaches} detaches, ${notDetachable} refused`);
});
