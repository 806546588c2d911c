// The join report of the module's last solve, part by part (wasm/report_bindings.cpp, the
// page's worker certifies after drawing): the same report as the solve's all-at-once one on
// every kind of scene, crossings included when asked; after an edit only the parts it changed
// are measured again; a wrong declared join is a report error, the mesh unharmed; asking for a
// report before any solve is a named error.
//   PDESURF_BUILD_DIR=build node --test tests/js/wasm-report.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { PdesurfError } from '../../web/solver/pdesurf-solver.js';
import { loadTestSolver } from './test-solver.mjs';

const root = new URL('../../', import.meta.url);
const scene = (id) => JSON.parse(readFileSync(new URL(`examples/${id}.json`, root), 'utf8'));
const grid = { nu: 16, nv: 16 };

function partByPart(solver, { crossings = false, budget = 0 } = {}) {
  const { parts } = solver.reportBegin({ crossings });
  let r, steps = 0;
  do {
    r = solver.reportStep(budget);
    ++steps;
  } while (!r.done);
  return { parts, steps, ...r };
}

test('part by part, the all-at-once report of every kind of scene, crossings when asked', async () => {
  const solver = await loadTestSolver();
  for (const id of ['you2004-fig4a', 'you2004-fig8c', 'bottle-solid', 'wu2015-fig4', 'zhang-vase-fig1b', 'you2004-fig2a', 'ref-pipe-tjoint']) {
    for (const crossings of [false, true]) {
      const s = scene(id);
      const whole = solver.solve(s, { ...grid, joins: true, crossings }).report;
      solver.solve(s, { ...grid, joins: false });
      const got = partByPart(solver, { crossings });
      assert.deepEqual(got.report, whole, `${id}, crossings ${crossings}`);
      assert.equal(got.report.crossingsChecked, crossings);
      assert.ok(got.parts >= whole.joins.length + 1, `${id}: ${got.parts} parts`);
    }
  }
});

test('with a budget of 0 one part a step; unchanged surfaces are kept, an edit measures again what it changed', async () => {
  const solver = await loadTestSolver();
  const s = scene('you2004-fig8d');
  solver.solve(s, { ...grid, joins: false });
  const first = partByPart(solver);
  assert.equal(first.steps, first.parts, 'one part a step');
  assert.equal(first.measured, first.parts);
  solver.solve(s, { ...grid, joins: false });
  const again = partByPart(solver);
  assert.equal(again.measured, 0, 'the same scene measured again');
  assert.equal(again.kept, first.parts);
  assert.deepEqual(again.report, first.report);
  // The stabiliser's dihedral: its root blends, tips and the tail's fills change, the wings not.
  s.parameters.stab_dihedral.value += 0.02;
  const whole = solver.solve(s, { ...grid, joins: true }).report;
  solver.solve(s, { ...grid, joins: false });
  const edited = partByPart(solver);
  assert.ok(edited.measured > 0 && edited.kept > 0, `${edited.measured} measured, ${edited.kept} kept`);
  assert.equal(edited.measured + edited.kept, first.parts);
  assert.deepEqual(edited.report, whole);
});

test('a wrong declared join is the report\'s error, not a failure; no report before a solve', async () => {
  const fresh = await loadTestSolver();
  assert.throws(() => fresh.reportStep(8), (e) => e instanceof PdesurfError && e.code === 'InvalidField' && /reportBegin first/.test(e.message));
  assert.throws(() => fresh.reportBegin(), (e) => e instanceof PdesurfError && e.code === 'InvalidField' && /solve first/.test(e.message));
  const s = scene('you2004-fig2a');
  s.patches[1].meets.at = 't1';
  const out = fresh.solve(s, { ...grid, joins: false });
  assert.ok(out.patches.length > 0);
  const r = partByPart(fresh);
  assert.equal(r.report.ok, false);
  assert.match(r.report.error.message, /is not the border/);
  // The next solve's report starts afresh.
  fresh.solve(scene('you2004-fig2a'), { ...grid, joins: false });
  assert.equal(partByPart(fresh).report.ok, true);
});
