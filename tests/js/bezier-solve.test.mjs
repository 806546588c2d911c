// The real wasm module through the page's wrapper and state: a bezier patch's extras
// (nets, normal arrows, energy, misfit) reach the page, and the page's edits (region
// weights, initial-net points, γ) change the solve the way the panel says they do.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { loadTestSolver } from './test-solver.mjs';
import { createSceneState } from '../../web/state/scene-state.js';

const root = new URL('../../', import.meta.url);
const solver = await loadTestSolver();
const GRID = { nu: 16, nv: 16 };

function open(id) {
  const state = createSceneState();
  state.setScene(JSON.parse(readFileSync(new URL(`examples/${id}.json`, root), 'utf8')), id);
  return state;
}
const solveHat = (state) => solver.solve(state.text(), GRID).patches.find((p) => p.kind === 'bezier');
const maxDiff = (a, b) => a.reduce((m, x, k) => Math.max(m, Math.abs(x - b[k])), 0);

test('a bezier patch brings its nets, normal arrows and numbers through the wrapper', () => {
  const hat = solveHat(open('wu2015-fig2'));
  assert.deepEqual(hat.netSize, [8, 8]);
  for (const key of ['controlNet', 'initialNet']) {
    assert.ok(hat[key] instanceof Float64Array && hat[key].length === 3 * 64, key);
  }
  assert.equal(hat.normalOrigins.length, 3 * 17 * 17); // one arrow per sample of the 16×16 grid
  assert.equal(hat.normalVectors.length, hat.normalOrigins.length);
  assert.equal(hat.lambda, 10);
  assert.equal(hat.gamma, 0);
  assert.ok(hat.energy > 0 && hat.normalMisfit > 0);
  // The fixed ring is S's ring, bit for bit.
  for (const k of [0, 7, 56, 63]) {
    assert.deepEqual(Array.from(hat.controlNet.slice(3 * k, 3 * k + 3)), Array.from(hat.initialNet.slice(3 * k, 3 * k + 3)));
  }
});

// Mean tilt (1 − n_z) of the surface normals over the middle region, where Fig. 2's guiding normals are (0, 0, 1).
function middleTilt(p) {
  let sum = 0, n = 0;
  for (let iv = 6; iv <= 10; iv++) {
    for (let iu = 6; iu <= 10; iu++) {
      sum += 1 - Math.abs(p.normals[3 * (iv * (GRID.nu + 1) + iu) + 2]);
      n++;
    }
  }
  return sum / n;
}

test('a heavier λ weight in the middle region flattens the middle further', () => {
  const state = open('wu2015-fig2');
  const before = solveHat(state);
  state.setRegionWeights('hat', [1, 1, 1, 1, 10, 1, 1, 1, 1]);
  const after = solveHat(state);
  assert.ok(maxDiff(after.positions, before.positions) > 1e-3, 'the surface did not move');
  assert.ok(middleTilt(after) < 0.8 * middleTilt(before), `tilt ${middleTilt(after)} against ${middleTilt(before)}`);
  // The misfit the solver reports is weighted by λ's weights, so it is not compared here.
  state.setRegionWeights('hat', new Array(9).fill(1));
  assert.deepEqual(solveHat(state).positions, before.positions);
});

test('an interior point of the initial net acts only through γ; a border point always', () => {
  const state = open('wu2015-fig2');
  const base = solveHat(state);
  state.setControlPointCoordinate('hat', 3, 4, 'z', 1.5);
  assert.deepEqual(solveHat(state).positions, base.positions, 'γ = 0: S\'s interior must not matter');

  state.setBezierNumber('hat', 'gamma', 20);
  const pulled = solveHat(state);
  state.setControlPointCoordinate('hat', 3, 4, 'z', 0.722394); // back to the example's value
  const unpulled = solveHat(state);
  assert.ok(maxDiff(pulled.positions, unpulled.positions) > 1e-3, 'γ > 0: the edit did not move the surface');
  assert.ok(Math.abs(pulled.initialNet[3 * (3 * 8 + 4) + 2] - 1.5) < 1e-6, 'initialNet shows the edit');

  state.setControlPointCoordinate('hat', 0, 4, 'z', 0.5); // a border point moves the boundary itself
  const border = solveHat(state);
  assert.ok(Math.abs(border.controlNet[3 * 4 + 2] - 0.5) < 1e-6);
});
