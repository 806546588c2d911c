// The page builds uvs and indices itself (web/viewer/grid-topology.js) instead of receiving
// them with every solve: they must be exactly what the core's tessellation makes, and a
// solve asked for no topology must leave them out.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { gridTopology } from '../../web/viewer/grid-topology.js';
import { loadSolver } from '../../web/solver/pdesurf-solver.js';

const REPO = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const scene = fs.readFileSync(path.join(REPO, 'examples', 'you2004-fig2a.json'), 'utf8');

test('grid topology matches the core, and topology: false leaves it out', async () => {
  const solver = await loadSolver({
    moduleUrl: new URL('../../build/wasm/pdesurf.js', import.meta.url).href,
    wasmBinary: fs.readFileSync(path.join(REPO, 'build', 'wasm', 'pdesurf.wasm')),
  });
  for (const [nu, nv] of [[1, 1], [4, 7], [64, 64], [255, 97], [333, 1]]) {
    const core = solver.solve(scene, { nu, nv }).patches[0];
    const page = gridTopology(nu, nv);
    assert.deepEqual(page.uvs, core.uvs, `uvs ${nu}x${nv}`);
    assert.deepEqual(page.indices, core.indices, `indices ${nu}x${nv}`);
    const lean = solver.solve(scene, { nu, nv, topology: false }).patches[0];
    assert.equal(lean.uvs, undefined);
    assert.equal(lean.indices, undefined);
    assert.deepEqual(lean.positions, core.positions);
  }
  assert.equal(gridTopology(8, 8), gridTopology(8, 8), 'cached for the latest grid');
});
