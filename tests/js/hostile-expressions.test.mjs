// Expressions that explode as trees (tests/hostile/expressions.json): the wasm module gives the
// manifest's verdict (as the CLI does, tests/cli/hostile-expressions.test.mjs) for the scene
// and its link, each within 5 s, with joins and curvature asked as the page does; afterwards
// the heap is under 300 MB and the module still solves.
import { describe, it, before } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { decodeFragment } from '../../web/link/link-codec.js';
import { loadSolver, PdesurfError } from '../../web/solver/pdesurf-solver.js';

const REPO = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const HOSTILE = path.join(REPO, 'tests', 'hostile');
const MANIFEST = JSON.parse(fs.readFileSync(path.join(HOSTILE, 'expressions.json'), 'utf8'));
const WASM = path.join(REPO, 'build', 'wasm');

describe('hostile expressions (wasm)', () => {
  let solver;
  before(async () => {
    solver = await loadSolver({
      moduleUrl: new URL('../../build/wasm/pdesurf.js', import.meta.url).href,
      wasmBinary: fs.readFileSync(path.join(WASM, 'pdesurf.wasm')),
    });
  });
  const options = { nu: MANIFEST.grid, nv: MANIFEST.grid, curvature: true, joins: true };

  function expectVerdict(c, solve) {
    const t0 = performance.now();
    let got = 'ok';
    let why = '';
    try {
      solve();
    } catch (err) {
      assert.ok(err instanceof PdesurfError, String(err));
      got = err.code;
      why = err.message;
      assert.match(why, /patches\[\d+\]\.ends\.u[01]/);
    }
    const ms = performance.now() - t0;
    assert.equal(got, c.verdict, why);
    assert.ok(ms <= 5000, `${ms.toFixed(0)} ms`);
  }

  for (const c of MANIFEST.cases) {
    it(`${c.name}: ${c.verdict} from the file and from the link, each within 5 s`, async () => {
      expectVerdict(c, () => solver.solve(fs.readFileSync(path.join(HOSTILE, c.scene), 'utf8'), options));
      const state = await decodeFragment(fs.readFileSync(path.join(HOSTILE, c.link), 'utf8'));
      expectVerdict(c, () => solver.solve(state.scene, options));
    });
  }

  it('leaves the heap under 300 MB and the module solving', () => {
    const vase = fs.readFileSync(path.join(REPO, 'examples', 'zhang-vase-fig2a.json'), 'utf8');
    const r = solver.solve(vase, { nu: 32, nv: 32 });
    assert.ok(r.patches.length > 0);
    assert.ok(solver.module.HEAP8.length < 300 << 20, `${solver.module.HEAP8.length >> 20} MiB`);
  });
});
