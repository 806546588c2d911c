// pdesurf export to STEP and IGES, read back by Open CASCADE (tests/occt/occt_readback): every
// example, each file a valid shape with one face per patch, named after it, within the
// tolerance of the core's surface at grid points that do not line up with the knots. A fit
// loosened past the tolerance fails the same check; an unreachable tolerance is a named error
// that leaves no file. The joins between the written faces are those `pdesurf check` finds
// between the surfaces, each within both faces' deviations, G1 and up with normals within
// 0.01°. The STEP and IGES files' topology as OCCT reads it is what pdesurf says it wrote (shared edges,
// free edges, closed shells and solids with their volume), and for three models what their
// shape implies (issue 36). docs/cad-export.md.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn, spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';

const root = new URL('../../', import.meta.url).pathname;
const cli = process.env.PDESURF_CLI ?? join(root, 'build/native/pdesurf');
const readback = process.env.PDESURF_OCCT_READBACK ?? join(dirname(cli), 'tests/occt/occt_readback');
const sanitized = process.env.PDESURF_CLI_SANITIZED === '1';
const dir = mkdtempSync(join(tmpdir(), 'pdesurf-cad-'));
const example = (id) => join(root, 'examples', `${id}.json`);
const GRID = '7x11'; // odd counts: the samples fall between knots

function runAsync(cmd, args) {
  return new Promise((resolve) => {
    const p = spawn(cmd, args);
    let stdout = '', stderr = '';
    p.stdout.on('data', (d) => (stdout += d));
    p.stderr.on('data', (d) => (stderr += d));
    p.on('close', (status) => resolve({ status, stdout, stderr }));
  });
}

// The core's own surface at grid points, per patch: (u, v, x, y, z) from `pdesurf sample`.
function samples(id, patches, scenePath = example(id)) {
  return patches.map((name) => {
    const r = spawnSync(cli, ['sample', scenePath, '--patch', name, '--grid', GRID], { encoding: 'utf8' });
    assert.equal(r.status, 0, r.stderr);
    const rows = r.stdout.trim().split('\n').slice(1).map((l) => l.split(',').map(Number));
    return { name, samples: rows };
  });
}

function parseExport(stdout) {
  const tolerance = Number(/^tolerance (\S+)/m.exec(stdout)[1]);
  const patches = [...stdout.matchAll(/^ {2}(\S+): (exact|certified deviation (\S+))/gm)].map((m) => ({
    name: m[1], exact: m[2] === 'exact', deviation: m[3] ? Number(m[3]) : 0,
  }));
  // "  blend u0 - rippled t0: G1, gap 1.7e-15 (allowed 8e-06), normals 1.6e-11 deg (target 0.01): ok"
  const joins = [...stdout.matchAll(/^ {2}(\S+ \S+ - .+): (G[012]), gap (\S+) \(allowed (\S+)\)(?:, normals (\S+) deg \(target (\S+)\))?: (.+)$/gm)]
    .map((m) => ({ join: m[1], level: m[2], gap: Number(m[3]), allowed: Number(m[4]), normalDeg: m[5] === undefined ? null : Number(m[5]), verdict: m[7] }));
  // "topology: 22 faces, 53 edges (53 shared or seams, 0 free), 33 vertices" and one line a shell.
  const t = /^topology: (\d+) faces, (\d+) edges \((\d+) shared or seams, (\d+) free\), (\d+) vertices$/m.exec(stdout);
  const shells = [...stdout.matchAll(/^ {2}(closed shell \(a solid\), volume (\S+)|open shell): /gm)].map((m) => ({ closed: m[2] !== undefined, volume: Number(m[2] ?? 0) }));
  const unshared = [...stdout.matchAll(/^ {2}not shared: (.+)$/gm)].map((m) => m[1]);
  const topology = t && { faces: Number(t[1]), edges: Number(t[2]), free: Number(t[4]), shells, unshared };
  return { tolerance, patches, joins, topology };
}

// What Open CASCADE must find in a STEP or IGES file, from what pdesurf says it wrote: the free
// edges (the model's open borders), no edge on more than two faces, every closed shell closed
// and a solid; when all are closed, their volume is pdesurf's.
function topologyExpectation(topology) {
  const closed = topology.shells.filter((s) => s.closed);
  const allClosed = closed.length === topology.shells.length;
  const out = { freeEdges: topology.free, edgesOnMoreThanTwoFaces: 0, closedShells: closed.length, solids: closed.length };
  if (allClosed) out.volume = closed.reduce((a, s) => a + s.volume, 0);
  return out;
}

// The joins `pdesurf check` certifies between the surfaces: the same ones are measured between
// the written faces, each within both faces' deviations and, G1 and up, normals within 0.01°.
function checkFittedJoins(id, joins, scenePath = example(id)) {
  const checked = spawnSync(cli, ['check', scenePath, '--json', '--grid', '4x4'], { encoding: 'utf8' });
  const expected = JSON.parse(checked.stdout).joins.length;
  assert.equal(joins.length, expected, `${id}: ${joins.length} joins of the faces, ${expected} of the surfaces`);
  for (const j of joins) {
    assert.equal(j.verdict, 'ok', `${id} ${j.join}`);
    assert.ok(j.gap <= j.allowed, `${id} ${j.join}: gap ${j.gap} > ${j.allowed}`);
    if (j.level !== 'G0') assert.ok(j.normalDeg <= 0.01, `${id} ${j.join}: normals ${j.normalDeg} deg`);
  }
}

async function exportAndReadBack(id, ext, scenePath = example(id)) {
  const file = join(dir, `${id}.${ext}`);
  const r = await runAsync(cli, ['export', scenePath, '-o', file]);
  assert.equal(r.status, 0, `${id}.${ext}: ${r.stderr}`);
  const { tolerance, patches, joins, topology } = parseExport(r.stdout);
  for (const p of patches) assert.ok(p.deviation <= tolerance, `${id} ${p.name}: ${p.deviation} > ${tolerance}`);
  checkFittedJoins(id, joins, scenePath);
  assert.ok(topology, `${id}: no topology line`);
  assert.deepEqual(topology.unshared, [], `${id}: every join is a shared edge`);
  const expect = join(dir, `${id}.${ext}.expect.json`);
  const wanted = { tolerance, faces: samples(id, patches.map((p) => p.name), scenePath) };
  wanted.topology = topologyExpectation(topology);
  writeFileSync(expect, JSON.stringify(wanted));
  const back = await runAsync(readback, [file, expect]);
  const report = JSON.parse(back.stdout || '{}');
  assert.equal(back.status, 0, `${id}.${ext}: ${JSON.stringify(report.errors)} ${back.stderr.slice(0, 400)}`);
  assert.equal(report.valid, true);
  assert.equal(report.faceCount, patches.length);
  for (const f of report.faces) assert.ok(f.maxDeviation <= tolerance, `${id} ${f.name}: ${f.maxDeviation}`);
  const expected = KNOWN_TOPOLOGY[id];
  if (expected) {
    for (const [key, value] of Object.entries(expected)) assert.equal(report[key], value, `${id}: ${key}`);
  }
  return report;
}

// The models whose shape is known (issue 36): the aeroplane one solid with no free edge; fig4a
// one open shell whose free edges are the cylinder's far ring and the plane's outer one; fig8c
// three open shells (a fill ringed by strips each), every strip's outer border and ends free;
// the bottle one solid; the imported part (a NURBS body, a cylinder, a blend and two fills) one solid.
const KNOWN_TOPOLOGY = {
  'you2004-fig8d': { solids: 1, closedShells: 1, freeEdges: 0 },
  'you2004-fig4a': { solids: 0, shells: 1, freeEdges: 2 },
  'you2004-fig8c': { solids: 0, shells: 3, freeEdges: 36 },
  'bottle-solid': { solids: 1, closedShells: 1, freeEdges: 0 },
  'cad-part': { solids: 1, closedShells: 1, freeEdges: 0 },
};

// Under AddressSanitizer (the sanitize row) two small examples; natively every one, the
// aeroplane too (22 patches, 14 s a file).
const index = JSON.parse(readFileSync(join(root, 'examples/index.json'), 'utf8'));
const ids = (index.examples ?? index).map((e) => e.id ?? e);
const chosen = sanitized ? ['you2004-fig4a', 'wu2015-fig1a'] : ids;

test('the Open CASCADE read-back tool is built', () => {
  assert.ok(existsSync(readback), `${readback} is missing: scripts/test builds it (OCCT from Debian's libocct-*-dev)`);
});

test(`every example (${chosen.length}) exported as STEP and IGES reads back in Open CASCADE within its tolerance`, async () => {
  const jobs = [];
  for (const id of chosen) jobs.push([id, 'step'], [id, 'igs']);
  // Two at a time: the machine has two cores. Every file is tried; the failures are listed.
  let next = 0;
  const failures = [];
  const worker = async () => {
    while (next < jobs.length) {
      const [id, ext] = jobs[next++];
      try {
        await exportAndReadBack(id, ext);
      } catch (e) {
        failures.push(e.message.split('\n')[0]);
      }
    }
  };
  await Promise.all([worker(), worker()]);
  assert.deepEqual(failures, []);
});

test('a closed ball beside an open tube: one solid and one open shell in the same STEP and IGES file', async () => {
  const scene = join(root, 'tests/fixtures/models/ball-and-tube.json');
  for (const ext of ['step', 'igs']) {
    const report = await exportAndReadBack('ball-and-tube', ext, scene);
    assert.deepEqual([report.solids, report.shells, report.closedShells, report.freeEdges], [1, 2, 1, 2], ext);
  }
});

// Issue 38 #8: no six-sided fill could be exported ("the fit's least-squares system is
// singular"), even on a flat hexagon that check passed.
test('a six-sided fill in a curved hexagonal hole: STEP and IGES read back, one open shell', async () => {
  const scene = join(root, 'tests/fixtures/models/hexagon-fill.json');
  for (const ext of ['step', 'igs']) {
    const report = await exportAndReadBack('hexagon-fill', ext, scene);
    assert.deepEqual([report.solids, report.shells], [0, 1], ext);
  }
});

// Random closed models from the space a user reaches: a tube of random radii (a cone frustum,
// or an elliptic or wavy section), height and placement, its rings capped by fills of 1 to 4
// sides (a ring split into that many ranges) at random heights, G1 or G2: every one one solid
// in STEP and IGES, no free edge, Open CASCADE's volume pdesurf's.
// Under AddressSanitizer the fills' fits take minutes: the models run natively only (the
// sanitize row covers the same code on the small examples above).
test('random capped tubes: one solid each in STEP and IGES, the volume pdesurf states', { skip: sanitized && 'natively only' }, async () => {
  let seed = 3608;
  const random = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
  const models = [];
  for (let k = 0; k < 3; ++k) {
    const r0 = 0.6 + 0.6 * random(), r1 = 0.6 + 0.6 * random(), h = 1 + 2 * random(), e = 0.7 + 0.6 * random(), w = 0.15 * random();
    const section = `(1 + ${w}*sin(3*v))`;
    const sides = (ring) => {
      const count = 1 + Math.floor(4 * random());
      if (count === 1) return [{ patch: 'tube', at: ring }];
      // Ranges inside the ring's [0, 2π], the first from 0 (the scene refuses a range through the seam).
      const cuts = [...Array(count).keys()].map((i) => (i === 0 ? 0 : (2 * Math.PI * (i + 0.6 * random() - 0.3)) / count));
      return cuts.map((c, i) => ({ patch: 'tube', at: ring, range: [c, i + 1 < count ? cuts[i + 1] : 2 * Math.PI] }));
    };
    const continuity = random() < 0.5 ? 'tangency' : 'curvature';
    const scene = {
      format: 'pdesurf-scene', version: 4, title: `random capped tube ${k}`,
      patches: [
        { name: 'tube', kind: 'surface', t_range: [0, 1], v_range: [0, '2*pi'],
          x: `(${r0} + ${r1 - r0}*t)*${section}*cos(v)`, y: `${e}*(${r0} + ${r1 - r0}*t)*${section}*sin(v)`, z: `${h}*t`,
          placement: { translate: [random() * 4 - 2, random() * 4 - 2, random() * 4 - 2], rotate: [360 * random(), 360 * random(), 360 * random()], scale: 0.5 + random() } },
        { name: 'bottom', kind: 'fill', borders: sides('t0'), height: 0.4 * random(), continuity },
        { name: 'top', kind: 'fill', borders: sides('t1'), height: 0.4 * random(), continuity },
      ],
    };
    const file = join(dir, `random-tube-${k}.json`);
    writeFileSync(file, JSON.stringify(scene));
    models.push({ k, scene, file });
  }
  // Two at a time, as the examples: the machine has two cores.
  const check = async ({ k, scene, file }) => {
    const checked = spawnSync(cli, ['check', file, '--json', '--grid', '8x8'], { encoding: 'utf8' });
    assert.ok(checked.stdout, `${checked.stderr} ${JSON.stringify(scene)}`);
    const bodies = JSON.parse(checked.stdout).bodies;
    assert.equal(bodies.length, 1, JSON.stringify(scene));
    assert.ok(bodies[0].closed, JSON.stringify(scene));
    for (const ext of ['step', 'igs']) {
      const report = await exportAndReadBack(`random-tube-${k}`, ext, file);
      assert.deepEqual([report.solids, report.closedShells, report.freeEdges], [1, 1, 0], `${ext}: ${JSON.stringify(scene)}`);
      assert.ok(Math.abs(report.volume - bodies[0].volume) <= 1e-4 * bodies[0].volume, `${ext}: OCCT ${report.volume}, check ${bodies[0].volume}`);
    }
  };
  let next = 0;
  const worker = async () => {
    while (next < models.length) await check(models[next++]);
  };
  await Promise.all([worker(), worker()]);
});

test('a fit made worse than the tolerance fails the same read-back', async () => {
  const file = join(dir, 'loose.step');
  const r = spawnSync(cli, ['export', example('you2004-fig4a'), '-o', file, '--tol', '1e-2', '--degree', '3'], { encoding: 'utf8' });
  assert.equal(r.status, 0, r.stderr);
  const expect = join(dir, 'loose.expect.json');
  writeFileSync(expect, JSON.stringify({ tolerance: 1e-6, faces: samples('you2004-fig4a', ['blend', 'cylinder', 'plane']) }));
  const back = spawnSync(readback, [file, expect], { encoding: 'utf8' });
  assert.equal(back.status, 1);
  const report = JSON.parse(back.stdout);
  assert.equal(report.valid, true);
  assert.ok(report.faces.some((f) => f.maxDeviation > 1e-6), JSON.stringify(report.faces));
});

test('an unreachable tolerance names the patch and the deviation reached, and writes nothing', () => {
  const file = join(dir, 'never.step');
  const r = spawnSync(cli, ['export', example('you2004-fig4a'), '-o', file, '--tol', '1e-300'], { encoding: 'utf8' });
  assert.equal(r.status, 1);
  assert.match(r.stderr, /TooLarge: patch 'blend': the fit reached a certified deviation of \S+ \(tolerance 1e-300\)/);
  assert.equal(existsSync(file), false);
  assert.deepEqual(readdirSync(dir).filter((f) => f.startsWith('never')), []);
});

test('a tolerance that is not a positive finite number, or a degree other than 3 or 5, is refused before any work', () => {
  // Decimal only, as numbers in scenes (issue 38: 0x1p-10 and ' 1e-3' were read by strtod).
  for (const bad of ['0', '-1', 'nan', 'inf', '1e-3x', '', '0x1p-10', ' 1e-3', '+1e-3', 'infinity', '.5e-3']) {
    const r = spawnSync(cli, ['export', example('you2004-fig4a'), '-o', join(dir, 'bad.step'), '--tol', bad], { encoding: 'utf8' });
    assert.equal(r.status, 1, bad);
    assert.match(r.stderr, /--tol expects a positive finite decimal number/);
  }
  const good = spawnSync(cli, ['export', example('you2004-fig4a'), '-o', join(dir, 'good.step'), '--tol', '1e-3'], { encoding: 'utf8' });
  assert.equal(good.status, 0, good.stderr);
  const r = spawnSync(cli, ['export', example('you2004-fig4a'), '-o', join(dir, 'bad.step'), '--degree', '4'], { encoding: 'utf8' });
  assert.match(r.stderr, /--degree expects 3 or 5/);
  assert.equal(existsSync(join(dir, 'bad.step')), false);
  // An empty scene: nothing to write, said so (it blamed a tolerance nobody gave).
  const empty = join(dir, 'empty.json');
  writeFileSync(empty, JSON.stringify({ format: 'pdesurf-scene', version: 4, patches: [] }));
  const e = spawnSync(cli, ['export', empty, '-o', join(dir, 'empty.step')], { encoding: 'utf8' });
  assert.equal(e.status, 1);
  assert.match(e.stderr, /InvalidField: patches: the scene has no patch to write as a CAD face/);
  assert.equal(existsSync(join(dir, 'empty.step')), false);
});

test('--jobs: the patches fitted on 1, 2 or 3 threads give the same file, the same error, and bad counts are refused', () => {
  // fig8c: 15 patches, fills among them; each thread solves its own copy of the scene.
  const bytes = [1, 2, 3].map((jobs) => {
    const file = join(dir, `jobs${jobs}.igs`);
    const r = spawnSync(cli, ['export', example('you2004-fig8c'), '-o', file, '--jobs', String(jobs)], { encoding: 'utf8' });
    assert.equal(r.status, 0, r.stderr);
    return readFileSync(file);
  });
  assert.ok(bytes[0].equals(bytes[1]) && bytes[0].equals(bytes[2]), 'the IGES files differ between thread counts');
  // Every patch fails at 1e-300: the error is the first patch handed out, whatever the threads.
  const errors = [1, 3].map((jobs) => {
    const r = spawnSync(cli, ['export', example('you2004-fig4a'), '-o', join(dir, 'never.igs'), '--tol', '1e-300', '--jobs', String(jobs)], { encoding: 'utf8' });
    assert.equal(r.status, 1);
    return r.stderr;
  });
  assert.equal(errors[0], errors[1]);
  for (const bad of ['0', '65', '-2', '1.5', 'two', '']) {
    const r = spawnSync(cli, ['export', example('you2004-fig4a'), '-o', join(dir, 'bad.step'), '--jobs', bad], { encoding: 'utf8' });
    assert.equal(r.status, 1, bad);
    assert.match(r.stderr, /--jobs expects a whole number from 1 to 64/);
  }
  const r = spawnSync(cli, ['check', example('you2004-fig4a'), '--jobs', '2'], { encoding: 'utf8' });
  assert.match(r.stderr, /--jobs apply to export only/);
});
