// Models of many patches (scene version 4: chained ends and fills, docs/chains-and-fills.md)
// through the wasm module and the page's wrapper: the aeroplane (you2004-fig8d) certifies
// like the CLI says, a second solve re-uses every patch, a wing's parameter re-solves only
// the patches downstream of it, bad models are named errors with nothing drawn; and the
// pure helpers the page uses for them (outliner chain, delete with dependents, join keys).
//   PDESURF_CLI=build/native/pdesurf PDESURF_BUILD_DIR=build node --test tests/js/wasm-models.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { spawnSync } from 'node:child_process';
import { PdesurfError } from '../../web/solver/pdesurf-solver.js';
import { loadTestSolver } from './test-solver.mjs';
import { upstreamOf } from '../../web/ui/outliner.js';
import { dependentsOf, downstreamOf, deletePatch } from '../../web/state/patch-delete.js';
import { normaliseReport, joinKey, centreText, seamText } from '../../web/state/join-report.js';

const root = new URL('../../', import.meta.url);
const solver = await loadTestSolver();
const cli = process.env.PDESURF_CLI ?? new URL('build/native/pdesurf', root).pathname;
const plane = () => JSON.parse(readFileSync(new URL('examples/you2004-fig8d.json', root), 'utf8'));
const byName = (patches) => Object.fromEntries(patches.map((p) => [p.name, p]));

test('the aeroplane certifies in the module as pdesurf check says: every join, every centre', () => {
  const { patches, report } = solver.solve(plane(), { nu: 16, nv: 16, joins: true });
  assert.ok(patches.length >= 12, `${patches.length} patches`);
  const native = JSON.parse(spawnSync(cli, ['check', new URL('examples/you2004-fig8d.json', root).pathname, '--json'], { encoding: 'utf8' }).stdout);
  assert.equal(native.ok, true);
  assert.equal(report.joins.length, native.joins.length);
  assert.ok(report.joins.every((j) => j.ok), JSON.stringify(report.joins.filter((j) => !j.ok)));
  assert.equal(report.centres.length, native.centres.length);
  assert.ok(report.centres.length >= 4 && report.centres.every((c) => c.ok && !c.fold));
  // Every closed patch joined to itself across v0 = v1: the fills closed to rounding (issue 35:
  // mid_top was torn by 0.1), the root blends sharp at the trailing edge by their data.
  assert.equal(report.seams.length, native.seams.length);
  assert.ok(report.seams.length >= 14 && report.seams.every((j) => j.ok), JSON.stringify(report.seams.filter((j) => !j.ok)));
  const seam = report.seams.find((j) => j.patch === 'mid_top');
  assert.ok(seam.level === 'G1' && seam.g0 < 1e-10 && seam.g1Deg < 1e-6, JSON.stringify(seam));
  // Join keys are unique even where one fill meets four patches.
  assert.equal(new Set(report.joins.map(joinKey)).size, report.joins.length);
  const s = byName(patches);
  assert.equal(s.mid_top.kind, 'fill');
  assert.deepEqual(s.front2.ends.u0, { patch: 'front1', at: 'u1' });
  assert.deepEqual([...s.mid_top.dependsOn].sort(), ['front2', 'rear1', 'rootL', 'rootR']);
});

test('a second solve re-uses every patch; a wing parameter re-solves only what is downstream of the wing', () => {
  const scene = plane();
  solver.solve(scene, { nu: 16, nv: 16 });
  const again = byName(solver.solve(scene, { nu: 16, nv: 16 }).patches);
  for (const p of Object.values(again)) if (p.kind === 'pde' || p.kind === 'fill') assert.equal(p.reused, true, p.name);
  const moved = plane();
  moved.parameters.wing_x.value = Math.min(moved.parameters.wing_x.max, moved.parameters.wing_x.value + 0.05 * (moved.parameters.wing_x.max - moved.parameters.wing_x.min));
  const after = byName(solver.solve(moved, { nu: 16, nv: 16 }).patches);
  const resolved = Object.values(after).filter((p) => (p.kind === 'pde' || p.kind === 'fill') && !p.reused).map((p) => p.name).sort();
  // The root blends follow the wings by reference, the tip caps close the wings' tips.
  assert.deepEqual(resolved, ['rootL', 'rootR', 'tipL', 'tipR']);
  // And the re-used ones draw exactly as before.
  assert.deepEqual(Array.from(after.front1.positions), Array.from(again.front1.positions));
});

test('bad models are named errors and nothing is drawn', () => {
  const cycle = plane();
  const front1 = cycle.patches.find((p) => p.name === 'front1');
  delete front1.boundary;
  front1.ends = { u0: { patch: 'front2', at: 'u1' }, u1: { patch: 'front2', at: 'u0' } };
  assert.throws(() => solver.solve(cycle, { nu: 8, nv: 8 }), (e) => e instanceof PdesurfError && e.code === 'InvalidField' &&
    /a cycle of references: 'front[12]' -> 'front[12]' -> 'front[12]'/.test(e.message));
  const open = plane();
  const top = open.patches.find((p) => p.name === 'mid_top');
  top.borders.splice(1, 1);
  assert.throws(() => solver.solve(open, { nu: 8, nv: 8 }), (e) => e instanceof PdesurfError && /the loop does not close: .* \(scene units\)/.test(e.message));
  const nine = plane();
  nine.patches.find((p) => p.name === 'mid_top').borders.push(...nine.patches.find((p) => p.name === 'mid_top').borders.slice(0, 4), nine.patches.find((p) => p.name === 'mid_top').borders[0]);
  assert.throws(() => solver.solve(nine, { nu: 8, nv: 8 }), /to 8 borders; this one has 9/);
  const fold = plane();
  fold.patches.find((p) => p.name === 'nose').centre = [5.3, 3, 0]; // far off to the side of the nose's loop
  assert.throws(() => solver.solve(fold, { nu: 8, nv: 8 }), /nose.*the fill folds/);
});

test('the outliner shows the chain; deleting a patch takes what is downstream of it, or refuses to detach a chain', () => {
  const scene = plane();
  const p = byName(scene.patches);
  assert.deepEqual(upstreamOf(p.front2), ['front1']);
  assert.deepEqual(upstreamOf(p.mid_top).sort(), ['front2', 'rear1', 'rootL', 'rootR']);
  assert.deepEqual(upstreamOf(p.rootL), ['wingL']);
  assert.deepEqual(upstreamOf(p.front1), []);
  assert.deepEqual(dependentsOf(scene, 'front1').map((d) => [d.patch, d.kind]), [['front2', 'chain'], ['nose', 'loop']]);
  assert.deepEqual(downstreamOf(scene, 'front1').sort(), ['front2', 'mid_bottom', 'mid_top', 'nose']);
  const before = structuredClone(scene);
  assert.throws(() => deletePatch(scene, 'front1', { dependents: 'detach' }), /cannot be detached; delete it too/);
  assert.deepEqual(scene, before);
  const gone = deletePatch(scene, 'front1', { dependents: 'delete' });
  assert.deepEqual([...gone].sort(), ['front1', 'front2', 'mid_bottom', 'mid_top', 'nose']);
  // What is left still solves and certifies.
  const { report } = solver.solve(scene, { nu: 8, nv: 8, joins: true });
  assert.ok(report.joins.every((j) => j.ok));
});

test('a seam shows as text, whatever the patch is called; a report without seams has none', () => {
  const seam = { patch: '<i>s</i>', end: 'v1', surface: '<i>s</i>', edge: 'v0', level: 'G0', g0: 4.47e-17, g1_deg: 17, g2_rel: null, fold: false, degenerate: 0, worst_u: 0.5, ok: true };
  const r = normaliseReport({ ok: true, scene_size: 1, joins: [], seams: [seam], crossings: [], centres: [] });
  assert.equal(r.seams.length, 1);
  assert.equal(seamText(r.seams[0]), '“<i>s</i>” seam v0 = v1 (sharp in its data): G0, gap 4.5e-17, angle 17°: ok');
  assert.equal(seamText({ ...r.seams[0], level: 'G2', g1Deg: null, ok: false }), '“<i>s</i>” seam v0 = v1: G2, gap 4.5e-17, angle —: FAILS');
  assert.deepEqual(normaliseReport({ ok: true, scene_size: 1, joins: [], crossings: [] }).seams, []);
});

test('a centre shows as text, whatever the patch is called', () => {
  const r = normaliseReport({ ok: true, scene_size: 1, joins: [], crossings: [], centres: [{ patch: '<b>x</b>', normal_spread_deg: 0.02, normal_spread_outer_deg: 1.2, fold: false, curvature_near: 3, curvature_ratio: 1.01, ok: true }] });
  assert.equal(r.centres.length, 1);
  assert.equal(centreText(r.centres[0]), '“<b>x</b>” centre: normal spread 0.020° (from 1.2°), no fold, curvature ratio 1.01: regular');
});

test('a PDE fill from picked borders: the loop found from their ends, solved G1; bad picks refused and the scene untouched', async () => {
  const { addLoopFill } = await import('../../web/state/scene-join.js');
  const c = 0.1;
  const strip = (k) => ({ name: `strip${k}`, kind: 'surface', t_range: [1, 2], v_range: [-1, 1],
    x: 't', y: 'v', z: 'c*(t^2 + v^2)', ...(k ? { placement: { rotate: [0, 0, 90 * k] } } : {}) });
  const scene = { format: 'pdesurf-scene', version: 4, parameters: { c: { value: c, min: 0, max: 0.3 } }, patches: [0, 1, 2, 3].map(strip) };
  // Border t0 of strip k: (1, v, c(1 + v²)) turned by 90k° about z, v from -1 to 1.
  const end = (k, v) => {
    const a = (Math.PI / 2) * k;
    return [Math.cos(a) - v * Math.sin(a), Math.sin(a) + v * Math.cos(a), c * (1 + v * v)];
  };
  const picks = [0, 2, 1, 3].map((k) => ({ surface: `strip${k}`, at: 't0' }));
  const endpoints = [0, 2, 1, 3].map((k) => [end(k, -1), end(k, 1)]);
  const before = structuredClone(scene);
  assert.throws(() => addLoopFill(scene, [...picks, ...picks, picks[0]], [...endpoints, ...endpoints, endpoints[0]]), /1 to 8 borders/);
  assert.throws(() => addLoopFill(scene, picks.slice(0, 3), endpoints.slice(0, 3)), /do not (form a closed loop|close)/);
  assert.throws(() => addLoopFill(scene, picks.slice(0, 1), endpoints.slice(0, 1)), /not closed: one border must be a closed curve/);
  assert.deepEqual(scene, before);
  const name = addLoopFill(scene, picks, endpoints);
  const fill = scene.patches.at(-1);
  assert.equal(fill.name, name);
  assert.equal(fill.kind, 'fill');
  assert.deepEqual(fill.borders.map((b) => b.patch), ['strip0', 'strip1', 'strip2', 'strip3']);
  const { report } = solver.solve(scene, { nu: 16, nv: 16, joins: true });
  assert.equal(report.joins.length, 4);
  assert.ok(report.joins.every((j) => j.ok && j.g1Deg < 1e-8), JSON.stringify(report.joins));
  assert.ok(report.centres[0].ok);
});
