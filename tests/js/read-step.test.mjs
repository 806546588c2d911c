// The page's STEP reader (issue 40, web/cad/read-step.js: Open CASCADE's wasm build) against
// `pdesurf import` (Debian's OCCT, natively) on the same files: the example part, pdesurf's
// own exports of seven examples (NURBS faces, closed ones among them) and a file of analytic
// faces; the same surfaces at the same (t, v) (both solved by the module), the faces in the
// same order. Bad files are named errors, the size judged before OCCT loads.
//   PDESURF_CLI=build/native/pdesurf node --test tests/js/read-step.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { loadTestSolver, wasmDir } from './test-solver.mjs';
import { readStep } from '../../web/cad/read-step.js';
import { OCCT_URL } from '../../web/cad/occt-url.js';
import { OCCT_WASM_BYTES } from '../../web/cad/occt-wasm-size.js';
import { CadFileError } from '../../web/cad/cad-scene.js';

const REPO = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const CLI = process.env.PDESURF_CLI ?? path.join(REPO, 'build', 'native', 'pdesurf');
const skip = !fs.existsSync(new URL('pdesurf.wasm', wasmDir)) ? `no wasm build in ${wasmDir}` : !fs.existsSync(CLI) ? `no CLI at ${CLI}` : false;
const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'pdesurf-read-step-'));
const grid = { nu: 8, nv: 12 };
// Under node the glue cannot fetch its wasm: it is read from beside it and handed over.
let occt = null;
const loadOpenCascade = () => (occt ??= import(OCCT_URL).then((mod) => mod.default({ wasmBinary: fs.readFileSync(new URL(OCCT_URL.replace(/\.js$/, '.wasm'))) })));

function cliImport(file) {
  const r = spawnSync(CLI, ['import', file], { encoding: 'utf8', maxBuffer: 1 << 26 });
  assert.equal(r.status, 0, r.stderr);
  return JSON.parse(r.stdout);
}

function exported(id) {
  const file = path.join(dir, `${id}.step`);
  const r = spawnSync(CLI, ['export', path.join(REPO, 'examples', `${id}.json`), '-o', file], { encoding: 'utf8' });
  assert.equal(r.status, 0, r.stderr);
  return file;
}

const files = () => [path.join(REPO, 'examples', 'cad', 'part.step'),
  ...['cad-part', 'ref-sphere-fillet', 'ref-torus-plane', 'ref-pipe-tjoint', 'you2004-fig4a', 'you2004-fig8c', 'bottle-solid'].map(exported)];

test("the download's total the page says is the installed Open CASCADE's wasm size", () => {
  // A new version of replicad-opencascadejs needs web/cad/occt-wasm-size.js updated.
  assert.equal(fs.statSync(new URL(OCCT_URL.replace(/\.js$/, '.wasm'))).size, OCCT_WASM_BYTES);
});

test('the page reads STEP files as pdesurf import does', { skip }, async () => {
  const solver = await loadTestSolver();
  let faces = 0, worst = 0;
  for (const file of files()) {
    const name = path.basename(file);
    const page = await readStep(fs.readFileSync(file), { fileName: name, loadOpenCascade });
    const cli = cliImport(file);
    assert.equal(page.patches.length, cli.patches.length, name);
    const a = solver.solve(JSON.stringify(page), grid).patches, b = solver.solve(JSON.stringify(cli), grid).patches;
    page.patches.forEach((p, k) => {
      const q = cli.patches[k];
      assert.deepEqual([p.t_range, p.v_range].flat().map((x) => +x.toPrecision(10)), [q.t_range, q.v_range].flat().map((x) => +x.toPrecision(10)), `${name} face ${k}: ranges`);
      assert.equal(Boolean(p.nurbs), Boolean(q.nurbs), `${name} face ${k}: NURBS in both or in neither`);
      const pa = a[k].positions, pb = b[k].positions;
      const size = Math.max(...pb.map(Math.abs));
      let gap = 0;
      for (let i = 0; i < pa.length; i += 3) gap = Math.max(gap, Math.hypot(pa[i] - pb[i], pa[i + 1] - pb[i + 1], pa[i + 2] - pb[i + 2]));
      worst = Math.max(worst, gap / size);
      assert.ok(gap <= 4e-7 * size, `${name} face ${k} (${q.name}): ${gap} apart (size ${size})`); // float32 positions
      faces++;
    });
  }
  assert.ok(faces >= 20, `${faces} faces`);
  console.log(`${faces} faces read by the page and by pdesurf import: worst ${worst.toExponential(2)} of the size apart`);
});

test('bad STEP files are named errors before the work', { skip }, async () => {
  await assert.rejects(readStep(new TextEncoder().encode('not a STEP file\n'), { loadOpenCascade }), (e) => e instanceof CadFileError && e.code === 'ParseError' && /could not read it as STEP/.test(e.message));
  await assert.rejects(readStep({ byteLength: 65 << 20 }, { loadOpenCascade: () => { throw new Error('loaded'); } }),
    (e) => e instanceof CadFileError && e.code === 'TooLarge' && /at most 64 MB/.test(e.message));
});
