// Detach through the page's state (web/state/ends-edit.js, scene-state.js) against the real
// wasm module: a curvature end detached beside a tangency end writes explicit orders, so the
// detached scene loads and solves to the same surface; a derived text longer than an
// expression may be is not written: the end keeps its reference and the reason is given.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { loadTestSolver } from './test-solver.mjs';
import { createSceneState } from '../../web/state/scene-state.js';
import { detachRefusal, EXPRESSION_CHARS } from '../../web/state/ends-edit.js';

const root = new URL('../../', import.meta.url);
const solver = await loadTestSolver();
const fillet = () => JSON.parse(readFileSync(new URL('examples/ref-sphere-fillet.json', root), 'utf8'));
const grid = { nu: 16, nv: 24 };
const maxDiff = (a, b) => a.reduce((m, x, k) => Math.max(m, Math.abs(x - b[k])), 0);
// A checksum of the blend's positions to 1e-9 (what "the same surface" means here).
const checksum = (positions) => positions.reduce((h, x) => (h * 31 + Math.round(x * 1e9)) % 2147483647, 7);

function solvedState(scene) {
  const state = createSceneState();
  state.setScene(scene, null);
  const result = solver.solve(state.text(), grid);
  state.noteSolved(result.patches);
  return { state, result };
}

test('a curvature end detached beside a tangency end: explicit orders, the scene loads and gives the same surface', () => {
  const first = solvedState(fillet());
  const state = first.state;
  state.setEndField('fillet', 'u1', 'continuity', 'curvature'); // as the page does: u0 stays tangency
  const result = solver.solve(state.text(), grid);
  state.noteSolved(result.patches);
  const blend = result.patches[0];
  assert.equal(blend.operator.x.order, 6);
  assert.equal(blend.ends.u1.derived.x.length, 3);
  state.detachEnd('fillet', 'u1', blend.ends.u1.derived);
  const written = state.patch('fillet');
  assert.deepEqual(Object.keys(written.ends), ['u0']);
  assert.deepEqual(written.operator, { order: 6, a: 1 }, 'the remaining tangency end alone would infer order 4');
  const again = solver.solve(state.text(), grid).patches[0];
  assert.ok(maxDiff(again.positions, blend.positions) < 1e-9, `${maxDiff(again.positions, blend.positions)}`);
  assert.equal(checksum(again.positions), checksum(blend.positions));
  // And the other end too: no end left by reference, still the same surface.
  state.noteSolved(solver.solve(state.text(), grid).patches);
  state.detachEnd('fillet', 'u0', again.ends.u0.derived);
  assert.equal(state.patch('fillet').ends, undefined);
  const typed = solver.solve(state.text(), grid).patches[0];
  assert.equal(checksum(typed.positions), checksum(blend.positions));
});

test('a derived text over the expression limit is not written: the end keeps its reference, and says why', () => {
  const scene = fillet();
  // A sphere whose x carries a sum in t, met along a curve: tau(v) replaces each t, so the
  // derived x(1) exceeds 1000 characters while every typed expression is within them.
  const sphere = scene.patches.find((p) => p.name === 'sphere');
  const extra = Array.from({ length: 24 }, (_, k) => `0.0001*cos(${k + 2}*v)*sin(t)`).join(' + ');
  sphere.x = `${sphere.x} + ${extra}`;
  scene.patches[0].ends.u1.at = { t: 'th0 + 0.1 + 0.05*sin(v)', replaces: 't0' };
  assert.ok(sphere.x.length <= EXPRESSION_CHARS);
  const { state, result } = solvedState(scene);
  const derived = result.patches[0].ends.u1.derived;
  assert.ok(derived.x.some((t) => t.length > EXPRESSION_CHARS), `${derived.x.map((t) => t.length)}`);
  const why = detachRefusal('u1', derived);
  assert.match(why, /^cannot detach: the derived x(ᵤ)?\(1\) has \d+ characters, more than an expression may have \(1000\); the end stays by reference$/);
  const before = state.text();
  assert.throws(() => state.detachEnd('fillet', 'u1', derived), (e) => e.message === why);
  assert.equal(state.text(), before, 'nothing half-applied');
  assert.equal(detachRefusal('u1', result.patches[0].ends.u0.derived), null);
});

test('an end on a NURBS surface (an imported face) is not detached: its border is B-spline data, said so', () => {
  const scene = JSON.parse(readFileSync(new URL('../../examples/cad-part.json', import.meta.url), 'utf8'));
  const { state, result } = solvedState(scene);
  const shoulder = result.patches.find((p) => p.name === 'shoulder');
  const onBody = shoulder.ends.u0.derived, onNeck = shoulder.ends.u1.derived;
  assert.ok(onBody.x.some((t) => t.includes('bspline(')), onBody.x.join(' | '));
  const why = detachRefusal('u0', onBody);
  assert.match(why, /^cannot detach: this end meets a NURBS surface/);
  const before = state.text();
  assert.throws(() => state.detachEnd('shoulder', 'u0', onBody), (e) => e.message === why);
  assert.equal(state.text(), before, 'nothing half-applied');
  assert.equal(detachRefusal('u1', onNeck), null, 'the neck is typed expressions: detachable');
});
