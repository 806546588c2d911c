// Scene version 3 through the real wasm module and the page's wrapper: a blend whose ends
// name their surfaces solves, reports its derived conditions as text (which, typed back as a
// version-2 blend, give the same surface), follows an edit of a surface, and a bad reference
// is a named error with the end's path and the v at fault.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { PdesurfError } from '../../web/solver/pdesurf-solver.js';
import { loadTestSolver } from './test-solver.mjs';

const root = new URL('../../', import.meta.url);
const solver = await loadTestSolver();
const fillet = () => JSON.parse(readFileSync(new URL('examples/ref-sphere-fillet.json', root), 'utf8'));
const grid = { nu: 16, nv: 24 };
const maxDiff = (a, b) => a.reduce((m, x, k) => Math.max(m, Math.abs(x - b[k])), 0);

test('derived conditions come back as text and, typed back, give the same blend', () => {
  const scene = fillet();
  const { patches } = solver.solve(JSON.stringify(scene), grid);
  const blend = patches[0];
  assert.deepEqual(Object.keys(blend.ends).sort(), ['u0', 'u1']);
  assert.equal(blend.ends.u0.surface, 'plane');
  for (const axis of ['x', 'y', 'z']) {
    assert.equal(blend.ends.u0.derived[axis].length, 2); // tangency at order 4: X and X_u
    assert.equal(blend.ends.u1.derived[axis].length, 2);
  }
  assert.match(blend.ends.u0.derived.x[0], /^2\.2\*cos\(v\)$/);
  // Detached: the same conditions typed as a version-2 boundary.
  const typed = structuredClone(scene);
  const b = typed.patches[0];
  b.boundary = {};
  for (const axis of ['x', 'y', 'z']) b.boundary[axis] = { u0: blend.ends.u0.derived[axis], u1: blend.ends.u1.derived[axis] };
  delete b.ends;
  b.operator = { order: 4, b: 1, c: 2, d: 1 };
  const again = solver.solve(JSON.stringify(typed), grid).patches[0];
  assert.ok(maxDiff(again.positions, blend.positions) < 1e-6, `${maxDiff(again.positions, blend.positions)}`);
});

test('editing a surface re-derives the blend', () => {
  const scene = fillet();
  const before = solver.solve(JSON.stringify(scene), grid).patches[0];
  scene.patches[1].x = '(a + 0.3 + t)*cos(v)';
  scene.patches[1].y = '(a + 0.3 + t)*sin(v)';
  const after = solver.solve(JSON.stringify(scene), grid).patches[0];
  assert.equal(after.ends.u0.derived.x[0], '2.5*cos(v)');
  assert.ok(maxDiff(after.positions, before.positions) > 0.1);
});

test('a bad reference is a named error with the end and the v at fault', () => {
  const scene = fillet();
  scene.patches[0].ends.u1.at = { t: 'th0 - 0.5 + 0.1*sin(v)' }; // below the sphere's t_range
  assert.throws(() => solver.solve(JSON.stringify(scene), grid), (e) => e instanceof PdesurfError && e.code === 'InvalidField'
    && /^patches\[0\]\.ends\.u1\.at: the trimline t = .* at v = .* is outside the t_range/.test(e.message));
  const missing = fillet();
  missing.patches[0].ends.u0.surface = 'nowhere';
  assert.throws(() => solver.solve(JSON.stringify(missing), grid), (e) => e.code === 'UnknownName' && /ends\.u0\.surface/.test(e.message));
  // The module is still alive.
  assert.equal(solver.solve(JSON.stringify(fillet()), grid).patches.length, 3);
});
