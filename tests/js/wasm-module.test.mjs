// The real wasm module under node, through the same wrapper the page uses: every example
// solves with the documented layout, errors arrive as PdesurfError with their code, and the
// module stays alive and correct after any number of failures and heap growth.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { spawnSync } from 'node:child_process';
import { PdesurfError } from '../../web/solver/pdesurf-solver.js';
import { loadTestSolver } from './test-solver.mjs';

const root = new URL('../../', import.meta.url);
const solver = await loadTestSolver();
const index = JSON.parse(readFileSync(new URL('examples/index.json', root), 'utf8'));
const sceneText = (file) => readFileSync(new URL(`examples/${file}`, root), 'utf8');

test('every example solves with the ParametricGeometry vertex layout, faces wound about their normals', () => {
  for (const { id, file } of index.examples) {
    const nu = 12, nv = 20, V = (nu + 1) * (nv + 1);
    const { patches } = solver.solve(sceneText(file), { nu, nv });
    assert.ok(patches.length >= 1, id);
    // One solved patch, or (seed 000 Fig. 8's models of many patches, the closed bottle, the imported part) several.
    const solved = patches.filter((p) => p.kind === 'pde' || p.kind === 'fill' || p.kind === 'bezier').length;
    if (id.startsWith('you2004-fig8') || id === 'bottle-solid' || id === 'cad-part') assert.ok(solved >= 1, id);
    else assert.equal(solved, 1, id);
    for (const p of patches) {
      assert.equal(p.positions.length, 3 * V);
      assert.equal(p.normals.length, 3 * V);
      assert.equal(p.uvs.length, 2 * V);
      assert.equal(p.indices.length, 6 * nu * nv);
      assert.ok(p.positions.every(Number.isFinite), `${id}/${p.name} positions finite`);
      for (let k = 0; k < V; k++) {
        const n = Math.hypot(p.normals[3 * k], p.normals[3 * k + 1], p.normals[3 * k + 2]);
        assert.ok(Math.abs(n - 1) < 1e-5, `${id}/${p.name} unit normal at ${k}`);
      }
      // Vertex (i, j) at j*(nu+1)+i with uv (i/nu, j/nv), as in three.js; the first cell's
      // triangles counter-clockwise about X_u × X_v (three.js winds them the other way).
      assert.equal(p.uvs[2 * (nu + 1) * 3 + 2 * 5], Math.fround(5 / nu));
      assert.equal(p.uvs[2 * (nu + 1) * 3 + 2 * 5 + 1], Math.fround(3 / nv));
      assert.deepEqual(Array.from(p.indices.slice(0, 6)), [0, 1, nu + 1, nu + 1, 1, nu + 2]);
    }
  }
});

test('wasm and native agree on the blend to float precision', () => {
  const cli = process.env.PDESURF_CLI ?? new URL('build/native/pdesurf', root).pathname;
  const file = new URL('examples/you2004-fig4a.json', root).pathname;
  const r = spawnSync(cli, ['sample', file, '--grid', '6x9'], { encoding: 'utf8' });
  assert.equal(r.status, 0, r.stderr);
  const rows = r.stdout.trim().split('\n').slice(1).map((l) => l.split(',').map(Number));
  const blend = solver.solve(sceneText('you2004-fig4a.json'), { nu: 6, nv: 9 }).patches[0];
  rows.forEach(([, , x, y, z], k) => {
    assert.ok(Math.abs(blend.positions[3 * k] - x) < 1e-6, `x at ${k}`);
    assert.ok(Math.abs(blend.positions[3 * k + 1] - y) < 1e-6, `y at ${k}`);
    assert.ok(Math.abs(blend.positions[3 * k + 2] - z) < 1e-6, `z at ${k}`);
  });
});

test('bad input is a PdesurfError naming the field; the module keeps working', () => {
  const good = sceneText('you2004-fig2a.json');
  const reference = solver.solve(good, { nu: 8, nv: 8 }).patches[0].positions;
  const cases = [
    ['{"format":', 8, 'ParseError', /malformed JSON/],
    [good.replace('"b": 1,', '"b": [1, 0, 1],'), 8, 'DegenerateOperator', /operator\.b\[1\]/],
    [good.replace('"r0p*cos(v)"', '"r0p*cos(v"'), 8, 'ParseError', /boundary\.x\.u0\[1\]: col 10: unbalanced '\(': missing '\)'/],
    [good.replace('"c": 2,', '"c": "exp(800)",'), 8, 'NonFinite', /operator\.c/],
    [good, 0, 'GridSize', /grid 0x8/],
    [good, 4096, 'GridSize', /grid 4096x8/],
    ['[' .repeat(100000), 8, 'TooLarge', /nested deeper/],
  ];
  for (let round = 0; round < 50; round++) {
    for (const [text, nu, code, message] of cases) {
      assert.throws(() => solver.solve(text, { nu, nv: 8 }), (e) =>
        e instanceof PdesurfError && e.code === code && message.test(e.message), `${code} ${message}`);
    }
  }
  assert.deepEqual(solver.solve(good, { nu: 8, nv: 8 }).patches[0].positions, reference);
});

test('results are copies that survive heap growth', () => {
  const small = solver.solve(sceneText('you2004-fig2a.json'), { nu: 4, nv: 4 }).patches[0].positions;
  const before = Array.from(small);
  const big = solver.solve(sceneText('you2004-fig2a.json'), { nu: 1024, nv: 1024 });
  assert.equal(big.patches[0].positions.length, 3 * 1025 * 1025);
  assert.deepEqual(Array.from(small), before);
});
