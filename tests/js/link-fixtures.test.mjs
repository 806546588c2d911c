// The stored links of tests/links/links.json still open (or are still refused) with
// today's decoder; the ones that open give scenes the solver accepts.
import { describe, it, before } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { decodeFragment, LinkError } from '../../web/link/link-codec.js';
import { loadSolver } from '../../web/solver/pdesurf-solver.js';

const REPO = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const FIXTURES = JSON.parse(fs.readFileSync(path.join(REPO, 'tests', 'links', 'links.json'), 'utf8'));
const WASM = path.join(REPO, 'build', 'wasm');
const KINDS = ['format', 'version', 'base64', 'deflate', 'size', 'json', 'scene'];

describe('stored links', () => {
  let solver = null;
  before(async () => {
    if (!fs.existsSync(path.join(WASM, 'pdesurf.wasm'))) return;
    solver = await loadSolver({
      moduleUrl: new URL('../../build/wasm/pdesurf.js', import.meta.url).href,
      wasmBinary: fs.readFileSync(path.join(WASM, 'pdesurf.wasm')),
    });
  });

  it('are well formed', () => {
    assert.equal(FIXTURES.format, 'pdesurf-link-fixtures');
    const names = FIXTURES.fixtures.map((f) => f.name);
    assert.equal(new Set(names).size, names.length, 'duplicate fixture names');
    for (const f of FIXTURES.fixtures) {
      assert.equal(typeof f.link, 'string', f.name);
      assert.ok(('expect' in f) !== ('error' in f), `${f.name}: needs exactly one of expect, error`);
      if (f.error) assert.ok(KINDS.includes(f.kind), `${f.name}: kind ${f.kind}`);
    }
    for (const required of ['unknown-version', 'truncated', 'bomb', 'v1-you2004-fig2a']) {
      assert.ok(names.includes(required), `missing fixture ${required}`);
    }
  });

  for (const f of FIXTURES.fixtures) {
    it(`${f.name}: ${f.error ? 'is refused' : 'opens'}`, async (t) => {
      const t0 = performance.now();
      if (f.error) {
        await assert.rejects(decodeFragment(f.link), (err) => {
          assert.ok(err instanceof LinkError, `${err}`);
          assert.ok(err.message.includes(f.error), `message "${err.message}" lacks "${f.error}"`);
          return true;
        });
        assert.ok(performance.now() - t0 < 2000, 'refusing took too long');
        return;
      }
      const state = await decodeFragment(f.link);
      assert.equal(state.scene.title, f.expect.title);
      const values = Object.fromEntries(Object.entries(state.scene.parameters || {}).map(([k, p]) => [k, p.value]));
      assert.deepEqual(values, f.expect.parameters);
      if (f.expect.grid) assert.deepEqual(state.grid, f.expect.grid);
      if (f.expect.camera) assert.deepEqual(state.camera, f.expect.camera);
      if (!solver) return t.diagnostic('no wasm build: scenes not solved');
      const result = solver.solve(state.scene, { nu: 8, nv: 8 });
      assert.ok(result.patches.length > 0);
    });
  }
});
