// The page's IGES reader (issue 40, web/cad/read-iges.js: entity 128 in plain JavaScript)
// against `pdesurf import` (Debian's Open CASCADE, natively) on the same files: pdesurf's own
// IGES exports of seven examples (faces, shells, solids, the aeroplane's 22 faces: a 4 MB
// scene; names kept), and random B-spline
// surfaces written here — degrees 1–5, rational or not, clamped or not, under transformation
// matrices (124), in inches, millimetres and metres, with another parameter
// delimiter. The same surfaces at the same (t, v) (both scenes solved by the module); chains of
// 124s against their product (Open CASCADE applies only the first). Then
// bad files: named errors, bounded before the work; 600 mutations of a real file.
//   PDESURF_CLI=build/native/pdesurf node --test tests/js/read-iges.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { loadTestSolver, wasmDir } from './test-solver.mjs';
import { random } from './bspline-samples.mjs';
import { readIges } from '../../web/cad/read-iges.js';
import { CadFileError } from '../../web/cad/cad-scene.js';

const REPO = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const CLI = process.env.PDESURF_CLI ?? path.join(REPO, 'build', 'native', 'pdesurf');
const skip = !fs.existsSync(new URL('pdesurf.wasm', wasmDir)) ? `no wasm build in ${wasmDir}` : !fs.existsSync(CLI) ? `no CLI at ${CLI}` : false;
const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'pdesurf-read-iges-'));
const grid = { nu: 10, nv: 12 };

function cliImport(file) {
  const r = spawnSync(CLI, ['import', file], { encoding: 'utf8', maxBuffer: 1 << 26 });
  assert.equal(r.status, 0, r.stderr);
  return JSON.parse(r.stdout);
}

// The faces of two scenes of the same file, solved by the module, matched one to one (each of
// the page's to the CLI's nearest): the worst distance of their points, in parts of the size.
function compare(solver, page, cli, label) {
  assert.equal(page.patches.length, cli.patches.length, `${label}: faces`);
  const a = solver.solve(JSON.stringify(page), grid).patches, b = solver.solve(JSON.stringify(cli), grid).patches;
  const gapOf = (pa, pb) => {
    let gap = 0;
    for (let i = 0; i < pa.length; i += 3) gap = Math.max(gap, Math.hypot(pa[i] - pb[i], pa[i + 1] - pb[i + 1], pa[i + 2] - pb[i + 2]));
    return gap;
  };
  let worst = 0;
  const used = new Set();
  a.forEach((pa, k) => {
    let best = -1, bestGap = Infinity;
    b.forEach((pb, j) => {
      if (used.has(j) || pb.positions.length !== pa.positions.length) return;
      const g = gapOf(pa.positions, pb.positions);
      if (g < bestGap) best = j, bestGap = g;
    });
    assert.ok(best >= 0, `${label}: face ${k} (${page.patches[k].name}) has no match`);
    used.add(best);
    const size = Math.max(...b[best].positions.map(Math.abs), 1e-300);
    worst = Math.max(worst, bestGap / size);
    assert.ok(bestGap <= 4e-7 * size, `${label}: face ${k} (${page.patches[k].name}): ${bestGap} apart (size ${size})`); // float32 positions
    assert.deepEqual([page.patches[k].t_range, page.patches[k].v_range].flat().map((x) => +x.toPrecision(9)),
      [cli.patches[best].t_range, cli.patches[best].v_range].flat().map((x) => +x.toPrecision(9)), `${label}: face ${k}: ranges`);
  });
  return worst;
}

test('the page reads pdesurf IGES exports as pdesurf import does, with their faces named', { skip }, async () => {
  const solver = await loadTestSolver();
  let faces = 0, worst = 0;
  for (const id of ['you2004-fig4a', 'ref-sphere-fillet', 'ref-pipe-tjoint', 'cad-part', 'bottle-solid', 'you2004-fig8c', 'you2004-fig8d']) {
    const file = path.join(dir, `${id}.igs`);
    const r = spawnSync(CLI, ['export', path.join(REPO, 'examples', `${id}.json`), '-o', file], { encoding: 'utf8' });
    assert.equal(r.status, 0, r.stderr);
    const page = readIges(fs.readFileSync(file, 'latin1'), { fileName: `${id}.igs` });
    worst = Math.max(worst, compare(solver, page, cliImport(file), id));
    // The scene's own patch names come back (the CLI's Open CASCADE names IGES faces "face k").
    const names = JSON.parse(fs.readFileSync(path.join(REPO, 'examples', `${id}.json`), 'utf8')).patches.map((p) => p.name);
    for (const p of page.patches) assert.ok(names.includes(p.name), `${id}: ${p.name} is one of its patches`);
    faces += page.patches.length;
  }
  assert.ok(faces >= 50, `${faces} faces`);
  console.log(`${faces} faces of pdesurf's IGES exports, page and pdesurf import: worst ${worst.toExponential(2)} of the size apart`);
});

// ---- IGES files written here (IGES 5.3, fixed form), independently of pdesurf's writer ----
const real = (x) => x.toExponential(16).replace('e', 'E'); // always a decimal point: a real
const record = (text, letter, seq) => `${text.padEnd(72)}${letter}${String(seq).padStart(7)}`;
const field = (x) => String(x).padStart(8);

// entities: [{ type, form, params (strings, type first), transform (DE of a 124 or 0), label, status }]
function igesText(entities, { unit = [2, 'MM'], delimiter = ',', end = ';' } = {}) {
  const pack = (tokens, width) => {
    const lines = [];
    let cur = '';
    tokens.forEach((t, k) => {
      const s = t + (k + 1 === tokens.length ? end : delimiter);
      if (cur.length + s.length > width) lines.push(cur), (cur = '');
      cur += s;
    });
    lines.push(cur);
    return lines;
  };
  const h = (s) => `${s.length}H${s}`;
  const global = [h(delimiter), h(end), h('test'), h('test.igs'), h('test'), h('test'), '32', '38', '6', '308', '15', h('test'), '1.', String(unit[0]), h(unit[1]),
    '1', '1.', h('20261205.120000'), '1.E-9', '1000.', h(''), h(''), '11', '0', h('20261205.120000')];
  const S = [record('pdesurf test file', 'S', 1)];
  const G = pack(global, 72).map((l, k) => record(l, 'G', k + 1));
  const D = [], P = [];
  entities.forEach((e, k) => {
    const de = 2 * k + 1;
    const lines = pack(e.params, 64);
    const first = P.length + 1;
    for (const l of lines) P.push(record(`${l.padEnd(64)} ${String(de).padStart(7)}`.slice(0, 72), 'P', P.length + 1));
    D.push(record(field(e.type) + field(first) + field(0) + field(0) + field(0) + field(0) + field(e.transform || 0) + field(0) + (e.status ?? '00000000'), 'D', de));
    D.push(record(field(e.type) + field(0) + field(0) + field(lines.length) + field(e.form ?? 0) + ' '.repeat(16) + (e.label ?? '').padStart(8) + field(0), 'D', de + 1));
  });
  const T = record(`S${String(S.length).padStart(7)}G${String(G.length).padStart(7)}D${String(D.length).padStart(7)}P${String(P.length).padStart(7)}`, 'T', 1);
  return [...S, ...G, ...D, ...P, T].join('\n') + '\n';
}

function knotVector(rnd, p, n, clampedEnds) {
  const t = [];
  if (clampedEnds) {
    for (let k = 0; k <= p; k++) t.push(0);
    const inner = n - p - 1;
    let x = 0;
    for (let k = 0; k < inner; k++) t.push((x += 0.2 + rnd()));
    const last = x + 0.2 + rnd();
    for (let k = 0; k <= p; k++) t.push(last);
  } else {
    let x = -rnd();
    for (let k = 0; k < n + p + 1; k++) t.push((x += 0.1 + rnd()));
  }
  return t;
}

// A random rotation (unit quaternion) with a translation: a 124's 12 numbers.
function randomMatrix(rnd) {
  let [a, b, c, d] = [rnd() - 0.5, rnd() - 0.5, rnd() - 0.5, rnd() - 0.5];
  const s = Math.hypot(a, b, c, d);
  [a, b, c, d] = [a / s, b / s, c / s, d / s];
  const R = [[a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)],
    [2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b)],
    [2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d]];
  return R.flatMap((r) => [...r, (rnd() - 0.5) * 20]);
}

function randomSurfaceEntities(rnd, entities, index, { chains = 1 } = {}) {
  const p = 1 + Math.floor(rnd() * 5), q = 1 + Math.floor(rnd() * 5);
  const nu = p + 1 + Math.floor(rnd() * 5), nv = q + 1 + Math.floor(rnd() * 5);
  const ku = knotVector(rnd, p, nu, rnd() < 0.7), kv = knotVector(rnd, q, nv, rnd() < 0.7);
  const rational = rnd() < 0.5;
  const w = [], xyz = [];
  for (let j = 0; j < nv; j++) {
    for (let i = 0; i < nu; i++) {
      w.push(rational ? 0.3 + 1.5 * rnd() : 1);
      xyz.push([i + rnd() * 0.5, j + rnd() * 0.5, 2 * Math.sin(i + 2 * j) + rnd()]);
    }
  }
  // Up to `chains` 124s, each the next one's own transform.
  let transform = 0;
  const chain = Math.floor(rnd() * (chains + 1));
  for (let k = 0; k < chain; k++) {
    entities.push({ type: 124, params: ['124', ...randomMatrix(rnd).map(real)], transform, status: '00010000' });
    transform = 2 * entities.length - 1;
  }
  let tail = ['0', '0'];
  if (rnd() < 0.5) {
    entities.push({ type: 406, form: 15, params: ['406', '1', `${`random ${index}`.length}Hrandom ${index}`], status: '00010000' });
    tail = ['0', '1', String(2 * entities.length - 1)];
  }
  const [U0, U1, V0, V1] = [ku[p], ku[nu], kv[q], kv[nv]];
  entities.push({ type: 128, params: ['128', String(nu - 1), String(nv - 1), String(p), String(q), '0', '0', rational ? '0' : '1', '0', '0',
    ...ku.map(real), ...kv.map(real), ...w.map(real), ...xyz.flat().map(real), real(U0), real(U1), real(V0), real(V1), ...tail], transform });
}

test('random B-spline surfaces, transformed and in other units, read as Open CASCADE reads them', { skip }, async () => {
  const solver = await loadTestSolver();
  const rnd = random(40);
  let worst = 0, faces = 0;
  const units = [[2, 'MM'], [1, 'IN'], [6, 'M']];
  for (let file = 0; file < 6; file++) {
    const entities = [];
    const count = 2 + Math.floor(rnd() * 4);
    for (let k = 0; k < count; k++) randomSurfaceEntities(rnd, entities, k);
    const text = igesText(entities, { unit: units[file % 3], delimiter: file === 5 ? '/' : ',' });
    const name = path.join(dir, `random-${file}.igs`);
    fs.writeFileSync(name, text);
    const page = readIges(text, { fileName: `random-${file}.igs` });
    worst = Math.max(worst, compare(solver, page, cliImport(name), `random file ${file} (${units[file % 3][1]})`));
    faces += count;
  }
  console.log(`${faces} random surfaces in 6 files, page and pdesurf import: worst ${worst.toExponential(2)} of the size apart`);
});

test('a chain of transformation matrices is their product (IGES 5.3 section 4.21)', () => {
  // Open CASCADE 7.6 applies only the surface's own 124 (the CLI cannot judge this): the same
  // surface under a chain of two and under one 124 holding their product, computed here.
  const rnd = random(41);
  for (let trial = 0; trial < 8; trial++) {
    const chained = [];
    randomSurfaceEntities(rnd, chained, 0, { chains: 0 });
    const surface = chained.pop();
    const A = randomMatrix(rnd), B = randomMatrix(rnd); // the surface's own B, B's own A
    const row = (m, i) => m.slice(4 * i, 4 * i + 4);
    const product = [0, 1, 2].flatMap((i) => [0, 1, 2, 3].map((j) => row(A, i)[0] * row(B, 0)[j] + row(A, i)[1] * row(B, 1)[j] + row(A, i)[2] * row(B, 2)[j] + (j === 3 ? row(A, i)[3] : 0)));
    const one = igesText([{ type: 124, params: ['124', ...product.map(real)], status: '00010000' }, { ...surface, transform: 1 }]);
    const two = igesText([{ type: 124, params: ['124', ...A.map(real)], status: '00010000' }, { type: 124, params: ['124', ...B.map(real)], transform: 1, status: '00010000' }, { ...surface, transform: 3 }]);
    const a = readIges(one).patches[0].nurbs.points.flat(2), b = readIges(two).patches[0].nurbs.points.flat(2);
    const size = Math.max(...a.map(Math.abs));
    a.forEach((x, k) => assert.ok(Math.abs(x - b[k]) <= 1e-13 * size, `trial ${trial}: ${x} against ${b[k]}`));
  }
});

test('bad IGES files are named errors, bounded before the work', () => {
  const rejects = (text, code, pattern) => assert.throws(() => readIges(text, { fileName: 'x.igs' }), (e) => {
    assert.ok(e instanceof CadFileError, String(e));
    assert.equal(e.code, code, e.message);
    assert.match(e.message, pattern);
    return true;
  });
  const surface = (overrides = {}) => ({ type: 128, params: ['128', '1', '1', '1', '1', '0', '0', '1', '0', '0', '0.', '0.', '1.', '1.', '0.', '0.', '1.', '1.',
    '1.', '1.', '1.', '1.', '0.', '0.', '0.', '1.', '0.', '0.', '0.', '1.', '0.', '1.', '1.', '0.', '0.', '1.', '0.', '1.'], ...overrides });
  const good = igesText([surface()]);
  assert.equal(readIges(good).patches.length, 1);
  rejects('not an IGES file\n', 'ParseError', /not an IGES file/);
  rejects(good.slice(0, good.indexOf('P      1') - 72), 'ParseError', /parameters lie outside the file/); // cut in the parameters
  rejects(igesText([surface({ params: surface().params.map((t, k) => (k === 26 ? 'NaN' : t)) })]), 'NonFinite', /^face 1 of 1 \(directory line 1\), parameter 26: "NaN" is not a finite number/);
  rejects(igesText([surface({ params: surface().params.map((t, k) => (k === 18 ? '0.' : t)) })]), 'InvalidField', /a weight is not positive/);
  // Counts and degree judged before any number is read: 200 × 200 poles, degree 30.
  rejects(igesText([surface({ params: ['128', '199', '199', '3', '3', '0', '0', '1', '0', '0'] })]), 'TooLarge', /200 × 200 control points/);
  rejects(igesText([surface({ params: ['128', '40', '40', '30', '3', '0', '0', '1', '0', '0'] })]), 'TooLarge', /degree 30/);
  rejects(igesText([surface({ params: ['128', '1', '1', '3', '1', '0', '0', '1', '0', '0'] })]), 'InvalidField', /not a B-spline surface's/);
  // 100 000 surfaces: counted before any is converted.
  const many = Array.from({ length: 100000 }, () => surface());
  const t0 = performance.now();
  rejects(igesText(many), 'TooLarge', /100000 faces: a scene holds at most 64/);
  assert.ok(performance.now() - t0 < 20000);
  // Only planes: nothing the page reads, said with the command that reads them.
  const plane = { type: 108, params: ['108', '0.', '0.', '1.', '0.', '0', '0.', '0.', '0.', '0.'] };
  rejects(igesText([plane, { type: 144, params: ['144', '1', '1', '0', '0'] }]), 'InvalidField', /plane \(entity 108\).*pdesurf import x\.igs/);
  // 70 faces on planes before 3 on B-splines: the three are read (faces the page does not read
  // do not count towards the 64), the planes named in the description.
  const mixed = [];
  for (let k = 0; k < 70; k++) mixed.push(plane, { type: 144, params: ['144', String(2 * mixed.length + 1), '1', '0', '0'] });
  for (let k = 0; k < 3; k++) mixed.push(surface(), { type: 144, params: ['144', String(2 * mixed.length + 1), '1', '0', '0'] });
  const read = readIges(igesText(mixed), { fileName: 'mixed.igs' });
  assert.equal(read.patches.length, 3);
  // A bounded surface (143) names its surface second, after its type.
  const bounded = readIges(igesText([surface(), { type: 143, params: ['143', '0', '1', '0'] }]), { fileName: 'bounded.igs' });
  assert.equal(bounded.patches.length, 1);
  assert.equal(bounded.patches[0].nurbs.points.length, 2);
  assert.match(read.description, / 70 faces on plane \(entity 108\) not read/);
  rejects('x'.repeat(10), 'ParseError', /not an IGES file/);
  assert.throws(() => readIges({ length: 65 << 20 }), (e) => e.code === 'TooLarge' && /at most 64 MB/.test(e.message));
});

test('mutated IGES files are read or refused by name, never another error', { skip }, async () => {
  // 600 mutations of a real file (pdesurf's export of fig4a): characters changed, lines cut,
  // lines repeated, numbers made huge or negative. Each is either a scene the module then
  // solves or refuses by name, or a CadFileError; never a TypeError, never a hang.
  const file = path.join(dir, 'mutate.igs');
  const r = spawnSync(CLI, ['export', path.join(REPO, 'examples', 'you2004-fig4a.json'), '-o', file], { encoding: 'utf8' });
  assert.equal(r.status, 0, r.stderr);
  const original = fs.readFileSync(file, 'latin1');
  const lines = original.split('\n');
  const solver = await loadTestSolver();
  const rnd = random(42);
  const pick = (n) => Math.floor(rnd() * n);
  const counts = { read: 0, refused: 0, solved: 0, solveRefused: 0 };
  for (let trial = 0; trial < 600; trial++) {
    let text;
    const kind = trial % 5;
    if (kind === 0) { // characters changed
      const a = original.split('');
      for (let k = 0; k < 1 + pick(8); k++) a[pick(a.length)] = ' 0123456789.,;-+EDH()xyz\n'[pick(25)];
      text = a.join('');
    } else if (kind === 1) { // cut anywhere
      text = original.slice(0, pick(original.length));
    } else if (kind === 2) { // a line dropped or repeated
      const l = [...lines];
      const at = pick(l.length);
      if (rnd() < 0.5) l.splice(at, 1); else l.splice(at, 0, l[at]);
      text = l.join('\n');
    } else if (kind === 3) { // a number made huge, negative or a fraction
      text = original.replace(/\d+(\.\d*)?(E[-+]?\d+)?/g, (m) => (rnd() < 0.02 ? ['1E308', '-7', '0.5', '99999999', '1E-320'][pick(5)] : m));
    } else { // a directory field changed
      const l = [...lines];
      const d = l.map((x, k) => (x[72] === 'D' ? k : -1)).filter((k) => k >= 0);
      const at = d[pick(d.length)];
      const f = pick(9);
      l[at] = l[at].slice(0, 8 * f) + String([0, 1, 3, -5, 99999, 124, 128, 510][pick(8)]).padStart(8) + l[at].slice(8 * f + 8);
      text = l.join('\n');
    }
    let scene;
    try {
      scene = readIges(text, { fileName: 'm.igs' });
      counts.read++;
    } catch (e) {
      assert.ok(e instanceof CadFileError, `trial ${trial} (kind ${kind}): ${e?.stack ?? e}`);
      assert.ok(e.code && e.message, `trial ${trial}: a code and a message`);
      counts.refused++;
      continue;
    }
    try {
      solver.solve(JSON.stringify(scene), { nu: 8, nv: 8 });
      counts.solved++;
    } catch (e) {
      assert.ok(e.code && e.code !== 'Internal', `trial ${trial} (kind ${kind}): the module's error ${e.code}: ${e.message}`);
      counts.solveRefused++;
    }
  }
  console.log(`600 mutated files: ${JSON.stringify(counts)}`);
});
