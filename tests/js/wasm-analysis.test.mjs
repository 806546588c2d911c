// The wasm module's analysis through the page's wrapper: curvature per vertex and the join
// certificate arrive with a solve, agree with the CLI's `pdesurf check --json`, and say what is
// wrong without losing the surface.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { spawnSync } from 'node:child_process';
import { loadTestSolver, wasmDir } from './test-solver.mjs';

const root = new URL('../../', import.meta.url);
const solver = await loadTestSolver();
const sceneText = (file) => readFileSync(new URL(`examples/${file}`, root), 'utf8');
const cli = process.env.PDESURF_CLI ?? new URL('build/native/pdesurf', root).pathname;

test('curvature per vertex: a sphere has K = 1/R² away from its poles, finite everywhere', () => {
  const scene = JSON.parse(sceneText('you2004-fig6.json'));
  const R = scene.parameters.R.value;
  const nu = 12, nv = 16;
  const { patches } = solver.solve(scene, { nu, nv, curvature: true });
  const sphere = patches.find((p) => p.name === 'sphere');
  assert.equal(sphere.gaussCurvature.length, (nu + 1) * (nv + 1));
  assert.ok(sphere.meanCurvature.every(Number.isFinite));
  for (let k = 0; k < sphere.gaussCurvature.length; k++) {
    if (k % (nu + 1) === 0) continue; // t = 0: the pole
    assert.ok(Math.abs(sphere.gaussCurvature[k] * R * R - 1) < 1e-4, `K at ${k}: ${sphere.gaussCurvature[k]}`);
    assert.ok(Math.abs(Math.abs(sphere.meanCurvature[k]) * R - 1) < 1e-4, `H at ${k}`);
  }
  assert.equal(sphere.degenerateVertices, nv + 1);
  // Without the option no curvature is computed or sent.
  assert.equal(solver.solve(scene, { nu, nv }).patches[0].meanCurvature, undefined);
});

test('the join report matches pdesurf check --json, join for join', () => {
  for (const file of ['you2004-fig2a.json', 'zhang-c2-ex1.json', 'wu2015-fig4.json', 'you2004-fig1.json']) {
    const { report } = solver.solve(sceneText(file), { nu: 16, nv: 16, joins: true, crossings: true });
    assert.equal(report.crossingsChecked, true);
    const r = spawnSync(cli, ['check', new URL(`examples/${file}`, root).pathname, '--json', '--grid', '48x48'], { encoding: 'utf8' });
    const native = JSON.parse(r.stdout);
    assert.equal(report.ok, native.ok, file);
    assert.equal(report.joins.length, native.joins.length, file);
    report.joins.forEach((j, k) => {
      const n = native.joins[k];
      for (const key of ['patch', 'end', 'surface', 'edge', 'level', 'fold', 'ok']) assert.equal(j[key], n[key], `${file} ${key}`);
      assert.ok(j.g2Rel === n.g2_rel || Math.abs(j.g2Rel - n.g2_rel) < 1e-9, `${file} g2: ${j.g2Rel} vs ${n.g2_rel}`);
      assert.ok(Math.abs(j.g0 - n.g0) < 1e-12 && Math.abs(j.g1Deg - n.g1_deg) < 1e-9, file);
    });
    assert.deepEqual(report.crossings.map((c) => [c.patch, c.other]), native.crossings.map((c) => [c.patch, c.other]), file);
  }
});

test('one serialiser: the module\'s raw report has the keys and the figures of pdesurf check --json', async () => {
  // The raw module, past the page's wrapper (which turns the report into the page's camelCase).
  const { default: create } = await import(new URL('pdesurf.js', wasmDir).href);
  const Module = await create({ wasmBinary: readFileSync(new URL('pdesurf.wasm', wasmDir)) });
  for (const file of ['bottle-solid.json', 'you2004-fig6.json', 'fill-four-strips.json']) {
    const raw = Module.solveSceneWith(sceneText(file), 48, 48, { curvature: false, joins: true, crossings: true, topology: false }).report;
    const r = spawnSync(cli, ['check', new URL(`examples/${file}`, root).pathname, '--json', '--grid', '48x48'], { encoding: 'utf8' });
    const native = JSON.parse(r.stdout);
    // The CLI adds what only it measures (the PDE residual, the creases); the module, whether it looked for crossings.
    const { interior, creases, ...shared } = native;
    assert.ok(interior && creases, file);
    const { crossings_checked: checked, ...module } = JSON.parse(JSON.stringify(raw));
    assert.equal(checked, true, file);
    const keys = (x) => (Array.isArray(x) ? x.map(keys) : x && typeof x === 'object' ? Object.fromEntries(Object.keys(x).sort().map((k) => [k, keys(x[k])])) : typeof x);
    assert.deepEqual(keys(module), keys(shared), `${file}: the same keys`);
    assert.equal(module.bodies.length, shared.bodies.length, file);
    module.bodies.forEach((b, k) => assert.ok(Math.abs(b.area - shared.bodies[k].area) <= 1e-9 * b.area, `${file}: area`));
  }
});

test('a broken join shows in the report; a wrong edge is a named report error and the surface still draws', () => {
  const scene = JSON.parse(sceneText('you2004-fig2a.json'));
  scene.patches[1].z = '0.3*t'; // a tilted plane: G1 fails by atan(0.3/0.5)
  let { report } = solver.solve(scene, { nu: 8, nv: 8, joins: true });
  const plane = report.joins.find((j) => j.surface === 'plane');
  assert.equal(plane.ok, false);
  assert.ok(Math.abs(plane.g1Deg - (Math.atan2(0.3, 0.5) * 180) / Math.PI) < 1e-6);
  assert.equal(report.ok, false);
  // Without {crossings: true} the (costly) crossing test does not run.
  assert.equal(report.crossingsChecked, false);
  assert.deepEqual(report.crossings, []);
  scene.patches[1].meets.at = 't1';
  const out = solver.solve(scene, { nu: 8, nv: 8, joins: true });
  assert.equal(out.patches.length, 3);
  assert.equal(out.report.error.code, 'InvalidField');
  assert.match(out.report.error.message, /is not the border u0 of 'blend'/);
});
