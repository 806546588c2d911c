// Importing a .3dm file (issue 40, web/cad/read-3dm.js): models exported as the page does it
// (the module's exportCad with format '3dm', then web/cad/write-3dm.js) and read back as
// scenes are the same surfaces at the same (u, v) within each face's certified deviation,
// named as before; blends by reference to the imported faces certify as on the originals;
// surfaces written by rhino3dm itself (a rational cylinder, closed in u: swapped) come back
// exact; bad files are named errors before the work.
//   node --test tests/js/read-3dm.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadTestSolver, wasmDir } from './test-solver.mjs';
import { write3dm } from '../../web/cad/write-3dm.js';
import { read3dm, CadFileError } from '../../web/cad/read-3dm.js';
import { loadRhino3dm } from '../../web/cad/load-rhino3dm.js';
import { random } from './bspline-samples.mjs';

const REPO = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const skip = fs.existsSync(new URL('pdesurf.wasm', wasmDir)) ? false : `no wasm build in ${wasmDir}`;
const example = (id) => JSON.parse(fs.readFileSync(path.join(REPO, 'examples', `${id}.json`), 'utf8'));
const PRIMARY = ['surface', 'ruled', 'separable'];
const grid = { nu: 9, nv: 13 };

const solverPromise = skip ? null : loadTestSolver();

async function roundTrip(solver, scene) {
  const fit = solver.exportCad(JSON.stringify(scene), { format: '3dm' });
  const bytes = await write3dm(fit.faces, { tolerance: fit.tolerance, title: fit.title, breps: fit.breps, archive: fit.archive });
  return { fit, imported: await read3dm(bytes, { fileName: 'model.3dm' }) };
}

const worstGap = (a, b) => a.reduce((m, x, k) => (k % 3 ? m : Math.max(m, Math.hypot(x - b[k], a[k + 1] - b[k + 1], a[k + 2] - b[k + 2]))), 0);

for (const id of ['ref-sphere-fillet', 'ref-torus-plane', 'ref-offset-cylinders-g2', 'cad-part']) {
  test(`${id}: exported to .3dm and imported, the same surfaces; its blends by reference certify on them`, { skip }, async () => {
    const solver = await solverPromise;
    const scene = example(id);
    const { fit, imported } = await roundTrip(solver, scene);
    assert.deepEqual(imported.patches.map((p) => p.name).sort(), scene.patches.map((p) => p.name).sort(), 'every face, named as its patch');
    const original = solver.solve(JSON.stringify(scene), grid).patches;
    const back = solver.solve(JSON.stringify(imported), grid).patches;
    for (const face of fit.faces) {
      const a = original.find((p) => p.name === face.name), b = back.find((p) => p.name === face.name);
      const size = Math.max(...a.positions.map(Math.abs));
      const gap = worstGap(a.positions, b.positions);
      // positions are float32: their rounding beside the certified deviation
      assert.ok(gap <= face.deviation + 2e-7 * size, `${id} ${face.name}: ${gap} from the original, certified ${face.deviation}`);
    }
    // The primaries replaced by their imported faces: the blends' joins certify again.
    const rebuilt = structuredClone(scene);
    rebuilt.version = 4;
    rebuilt.patches = scene.patches.map((p) => {
      if (!PRIMARY.includes(p.kind)) return p;
      const face = imported.patches.find((q) => q.name === p.name);
      return p.meets ? { ...face, meets: p.meets } : face;
    });
    const report = solver.solve(JSON.stringify(rebuilt), { ...grid, joins: true }).report;
    assert.ok(report.joins.length >= 2);
    for (const j of [...report.joins, ...report.seams]) assert.ok(j.ok, `${id}: ${j.patch}:${j.end} - ${j.surface}:${j.edge} G0 ${j.g0} G1 ${j.g1Deg}`);
    assert.ok(report.ok, `${id}: the imported model certifies`);
  });
}

test('a rational cylinder written by rhino3dm comes back exact, swapped so v runs around', { skip }, async () => {
  const rh = await loadRhino3dm();
  const file = new rh.File3dm();
  const attributes = new rh.ObjectAttributes();
  attributes.name = 'tube';
  file.objects().add(rh.Brep.createFromSurface(rh.NurbsSurface.createFromCylinder(new rh.Cylinder(new rh.Circle(2.0), 3.0))), attributes);
  const scene = await read3dm(file.toByteArray(), { fileName: 'tube.3dm' });
  assert.equal(scene.patches.length, 1);
  const [tube] = scene.patches;
  assert.equal(tube.name, 'tube');
  assert.deepEqual(tube.t_range, [0, 3], 't along the axis');
  assert.deepEqual(tube.v_range, [0, 2 * Math.PI], 'v around');
  assert.ok(tube.nurbs.weights, 'rational');
  const solver = await solverPromise;
  const [patch] = solver.solve(JSON.stringify(scene), grid).patches;
  let worst = 0;
  for (let k = 0; k < patch.positions.length; k += 3) worst = Math.max(worst, Math.abs(Math.hypot(patch.positions[k], patch.positions[k + 1]) - 2));
  assert.ok(worst < 1e-6, `radius within float32 of 2: ${worst}`);
});

test('bad .3dm files are named errors before the work', { skip }, async () => {
  const rh = await loadRhino3dm();
  const refusal = async (bytes, code, words, options = {}) => {
    await assert.rejects(read3dm(bytes, options), (e) => e instanceof CadFileError && e.code === code && words.test(e.message), String(words));
  };
  await refusal(new Uint8Array(64), 'ParseError', /could not read it as a \.3dm file/);
  // The size is judged before rhino3dm is even loaded.
  await refusal({ byteLength: 65 << 20 }, 'TooLarge', /at most 64 MB/, { loadRhino: () => { throw new Error('loaded'); } });
  const many = new rh.File3dm();
  for (let k = 0; k < 65; k++) many.objects().add(rh.NurbsSurface.createFromCylinder(new rh.Cylinder(new rh.Circle(1 + k), 1)), new rh.ObjectAttributes());
  await refusal(many.toByteArray(), 'TooLarge', /more than 64 faces/);
  const dense = rh.NurbsSurface.create(3, false, 4, 4, 130, 130);
  for (let i = 0; i < 130; i++) for (let j = 0; j < 130; j++) dense.points().set(i, j, [i, j, 0, 1]);
  for (let k = 0; k < dense.knotsU().count; k++) dense.knotsU().set(k, k), dense.knotsV().set(k, k);
  const one = new rh.File3dm();
  one.objects().add(dense, new rh.ObjectAttributes());
  await refusal(one.toByteArray(), 'TooLarge', /130 × 130 control points/);
  const empty = new rh.File3dm();
  await refusal(empty.toByteArray(), 'InvalidField', /no surfaces/);
});

test('random NURBS surfaces written by rhino3dm (degrees 1-5, rational or not, clamped or not) come back as rhino3dm evaluates them', { skip }, async () => {
  const rh = await loadRhino3dm();
  const solver = await solverPromise;
  const rnd = random(40);
  let worst = 0, surfaces = 0;
  for (let trial = 0; trial < 24; trial++) {
    const p = 1 + Math.floor(rnd() * 5), q = 1 + Math.floor(rnd() * 5);
    const nu = p + 1 + Math.floor(rnd() * 5), nv = q + 1 + Math.floor(rnd() * 5);
    const rational = trial % 2 === 1;
    const s = rh.NurbsSurface.create(3, rational, p + 1, q + 1, nu, nv);
    // Knots: openNURBS's n + p - 1, non-decreasing; clamped ends (p equal knots) or not.
    for (const [list, deg, n] of [[s.knotsU(), p, nu], [s.knotsV(), q, nv]]) {
      const clamped = rnd() < 0.6;
      let k = 0;
      for (let i = 0; i < n + deg - 1; i++) {
        if (i > 0) k += clamped && (i < deg || i >= n) ? 0 : 0.2 + rnd();
        list.set(i, k);
      }
    }
    for (let i = 0; i < nu; i++) {
      for (let j = 0; j < nv; j++) {
        const w = rational ? 0.5 + 1.5 * rnd() : 1;
        const x = [i + 0.3 * rnd(), j + 0.3 * rnd(), 0.5 * rnd()];
        s.points().set(i, j, [x[0] * w, x[1] * w, x[2] * w, w]);
      }
    }
    if (!s.isValid) continue;
    const file = new rh.File3dm();
    file.objects().add(s, new rh.ObjectAttributes());
    const scene = await read3dm(file.toByteArray(), { fileName: 'random.3dm' });
    const [patch] = scene.patches;
    const [solved] = solver.solve(JSON.stringify(scene), grid).patches;
    const [t0, t1] = patch.t_range, [v0, v1] = patch.v_range;
    let size = 0, gap = 0;
    for (let j = 0; j <= grid.nv; j++) {
      for (let i = 0; i <= grid.nu; i++) {
        const t = t0 + ((t1 - t0) * i) / grid.nu, v = v0 + ((v1 - v0) * j) / grid.nv;
        const want = s.pointAt(t, v), k = 3 * (j * (grid.nu + 1) + i);
        size = Math.max(size, Math.hypot(...want));
        gap = Math.max(gap, Math.hypot(solved.positions[k] - want[0], solved.positions[k + 1] - want[1], solved.positions[k + 2] - want[2]));
      }
    }
    assert.ok(gap <= 2e-7 * size, `trial ${trial} (degree ${p} × ${q}, ${rational ? 'rational' : 'polynomial'}): ${gap} from rhino3dm's pointAt`); // float32 positions
    worst = Math.max(worst, gap / size);
    surfaces++;
  }
  assert.ok(surfaces >= 20, `${surfaces} valid surfaces`);
  console.log(`${surfaces} random rhino3dm surfaces: worst ${worst.toExponential(2)} of the size from its own evaluation (float32 positions)`);
});

test('node scripts/import-3dm.mjs writes the scene the page reads; a bad file is a named error that writes nothing', { skip }, async () => {
  const { spawnSync } = await import('node:child_process');
  const os = await import('node:os');
  const solver = await solverPromise;
  const scene = example('cad-part');
  const fit = solver.exportCad(JSON.stringify(scene), { format: '3dm' });
  const bytes = await write3dm(fit.faces, { tolerance: fit.tolerance, title: fit.title, breps: fit.breps, archive: fit.archive });
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'pdesurf-3dm-'));
  const file = path.join(dir, 'part.3dm'), out = path.join(dir, 'part.json');
  fs.writeFileSync(file, bytes);
  const r = spawnSync(process.execPath, [path.join(REPO, 'scripts', 'import-3dm.mjs'), file, '-o', out], { encoding: 'utf8' });
  assert.equal(r.status, 0, r.stderr);
  assert.deepEqual(JSON.parse(fs.readFileSync(out, 'utf8')), await read3dm(bytes, { fileName: 'part.3dm' }));
  const junk = path.join(dir, 'junk.3dm'), nothing = path.join(dir, 'nothing.json');
  fs.writeFileSync(junk, Buffer.alloc(100));
  const bad = spawnSync(process.execPath, [path.join(REPO, 'scripts', 'import-3dm.mjs'), junk, '-o', nothing], { encoding: 'utf8' });
  assert.equal(bad.status, 1);
  assert.match(bad.stderr, /^import-3dm: .*junk\.3dm: ParseError: rhino3dm could not read it as a \.3dm file/);
  assert.ok(!fs.existsSync(nothing));
});
