// The pdesurf CLI as a user runs it: output shape, precision, boundary values, exit codes.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const root = new URL('../../', import.meta.url).pathname;
const cli = process.env.PDESURF_CLI ?? join(root, 'build/native/pdesurf');
const example = (id) => join(root, 'examples', `${id}.json`);
const run = (...args) => spawnSync(cli, args, { encoding: 'utf8' });

function parseCsv(text) {
  const [header, ...lines] = text.trim().split('\n');
  assert.equal(header, 'u,v,x,y,z');
  return lines.map((l) => l.split(',').map(Number));
}

test('sample prints (nu+1)(nv+1) rows including both ends, at full precision', () => {
  const r = run('sample', example('you2004-fig2a'), '--grid', '4x6');
  assert.equal(r.status, 0, r.stderr);
  const rows = parseCsv(r.stdout);
  assert.equal(rows.length, 5 * 7);
  const us = new Set(rows.map((x) => x[0]));
  assert.deepEqual([...us].sort((a, b) => a - b), [0, 0.25, 0.5, 0.75, 1]);
  assert.equal(Math.max(...rows.map((x) => x[1])), 2 * Math.PI);
  // u = 0 lies on the plane's trimline circle r0 = 1.8, u = 1 on the cone's (r1 = 0.6, h1 = 2).
  for (const [u, v, x, y, z] of rows) {
    if (u === 0) {
      assert.ok(Math.abs(Math.hypot(x, y) - 1.8) < 1e-12 && Math.abs(z) < 1e-12);
    }
    if (u === 1) {
      assert.ok(Math.abs(x - 0.6 * Math.cos(v)) < 1e-12 && Math.abs(z - 2) < 1e-12);
    }
  }
  assert.match(r.stdout, /\d\.\d{12,}/, 'full precision digits');
});

test('sample --patch picks a primary surface', () => {
  const r = run('sample', example('you2004-fig4a'), '--patch', 'plane', '--grid', '2x2');
  assert.equal(r.status, 0, r.stderr);
  const rows = parseCsv(r.stdout);
  assert.equal(rows.length, 9);
  assert.ok(rows.every((row) => Math.abs(row[4]) < 1e-15), 'the plane is z = 0');
});

test('export writes an OBJ with every patch: joined (the blend\'s two rings shared), or --patches each its own grid', () => {
  const dir = mkdtempSync(join(tmpdir(), 'pdesurf-cli-'));
  const out = join(dir, 'fig4a.obj');
  const loose = run('export', example('you2004-fig4a'), '-o', out, '--grid', '8x8', '--patches');
  assert.equal(loose.status, 0, loose.stderr);
  let obj = readFileSync(out, 'utf8');
  assert.deepEqual(obj.match(/^o .*/gm), ['o blend', 'o cylinder', 'o plane']);
  assert.equal(obj.match(/^v /gm).length, 3 * 81);
  assert.equal(obj.match(/^f /gm).length, 3 * 128);
  const r = run('export', example('you2004-fig4a'), '-o', out, '--grid', '8x8');
  assert.equal(r.status, 0, r.stderr);
  obj = readFileSync(out, 'utf8');
  assert.deepEqual(obj.match(/^o .*/gm), ['o blend', 'o cylinder', 'o plane']);
  // All three are closed around v (8 columns, the seam not repeated). The blend comes first and
  // writes its 9 rings; the cylinder and the plane share its end rings and write 8 of theirs.
  const parts = obj.split(/^o .*$/m).slice(1);
  assert.deepEqual(parts.map((p) => p.match(/^v /gm).length), [9 * 8, 8 * 8, 8 * 8]);
  for (const part of parts) assert.equal(part.match(/^f /gm).length, 128);
});

test('errors go to stderr with exit code 1 and name the field', () => {
  const dir = mkdtempSync(join(tmpdir(), 'pdesurf-cli-'));
  const cases = [
    [['sample', example('you2004-fig2a'), '--grid', '0x8'], /GridSize/],
    [['sample', example('you2004-fig2a'), '--grid', '4096x8'], /GridSize/],
    [['sample', example('you2004-fig2a'), '--grid', 'abc'], /--grid expects NUxNV/],
    [['sample', join(dir, 'missing.json')], /cannot read/],
    [['sample', example('you2004-fig2a'), '--patch', 'nope'], /no patch named 'nope'/],
    [['frobnicate'], /unknown command/],
  ];
  const bad = join(dir, 'bad.json');
  writeFileSync(bad, readFileSync(example('you2004-fig2a'), 'utf8').replace('"r0p*cos(v)"', '"r0q*cos(v)"'));
  cases.push([['sample', bad], /patches\[0\]\.boundary\.x\.u0\[1\]: col 1: unknown parameter 'r0q'/]);
  const zeroB = join(dir, 'zero-b.json');
  writeFileSync(zeroB, readFileSync(example('you2004-fig2a'), 'utf8').replace('"b": 1,', '"b": [1, 1, 0],'));
  cases.push([['sample', zeroB], /DegenerateOperator: patches\[0\]\.operator\.b\[2\]/]);
  for (const [args, message] of cases) {
    const r = run(...args);
    assert.equal(r.status, 1, `${args.join(' ')}: exit ${r.status}`);
    assert.equal(r.stdout, '', 'nothing on stdout');
    assert.match(r.stderr, message);
  }
});

test('sample --method picks the solver; compare --json reports every applicable method', () => {
  const fig1 = example('you2004-fig1');
  const closed = parseCsv(run('sample', fig1, '--grid', '4x4', '--method', 'closed').stdout);
  const navier = parseCsv(run('sample', fig1, '--grid', '4x4', '--method', 'pseudo-navier').stdout);
  assert.equal(closed.length, navier.length);
  const diff = Math.max(...closed.map((row, k) => Math.abs(row[2] - navier[k][2])));
  assert.ok(diff > 1e-6 && diff < 1e-2, `pseudo-Navier differs a little from the closed form: ${diff}`);
  const bad = run('sample', fig1, '--method', 'modal');
  assert.equal(bad.status, 1);
  assert.match(bad.stderr, /method 'modal' needs a number of terms/);
  // Refused by the method's parser, before the scene is solved (issue 38: fourier:4096 passed it).
  for (const [method, most] of [['fourier:4096', 1000], ['pseudo-spectral:1001', 1000], ['modal:4097', 4096], ['modal:+5', 4096], ['modal: 5', 4096]]) {
    const r = run('sample', fig1, '--method', method);
    assert.equal(r.status, 1, method);
    assert.match(r.stderr, new RegExp(`expected a whole number of terms from 1 to ${most}`), method);
  }

  const r = run('compare', fig1, '--json');
  assert.equal(r.status, 0, r.stderr);
  const rows = JSON.parse(r.stdout);
  const byName = Object.fromEntries(rows.map((row) => [row.method, row]));
  for (const name of ['closed', 'pseudo-navier', 'modal:16', 'fourier:20', 'fourier:100', 'pseudo-spectral:2', 'pseudo-spectral:5', 'reference']) {
    assert.ok(byName[name], `${name} present`);
    for (const key of ['E', 'bc_error', 'solve_us']) assert.ok(Number.isFinite(byName[name][key]), `${name}.${key}`);
  }
  assert.equal(byName.closed.E, 0);
  assert.ok(byName['pseudo-navier'].E <= 6.637916e-4);
  assert.ok(Math.abs(byName['fourier:20'].E / 6.565263e-2 - 1) < 0.1);
  const table = run('compare', fig1);
  assert.match(table.stdout, /E over 100x100 points against the closed solution/);
});

// Issue 38 #10: on a fill every method's E was nan (the typed problem of a fill is empty), and
// on a chained patch compare solved the typed problem without the conditions it derives.
test('compare measures the problem the scene solves: a fill\'s loop, a chained end\'s derived conditions', () => {
  for (const [file, patch] of [[example('bottle-solid'), 'cap'], [example('you2004-fig8d'), 'front2']]) {
    const r = run('compare', file, '--patch', patch, '--grid', '12x12', '--json');
    assert.equal(r.status, 0, r.stderr);
    const rows = JSON.parse(r.stdout).filter((row) => !row.error);
    assert.ok(rows.length >= 3, `${patch}: ${r.stdout.slice(0, 300)}`);
    for (const row of rows)
      for (const key of ['E', 'bc_error', 'residual']) assert.ok(Number.isFinite(row[key]), `${patch} ${row.method}.${key} = ${row[key]}`);
    // The methods that meet boundary data exactly meet the derived data: had compare dropped
    // them (a fill's are all there is), they would meet something else, or nothing.
    const exact = rows.filter((row) => /^(closed|pseudo-navier|modal:64)$/.test(row.method));
    assert.ok(exact.length >= 1, `${patch}: ${rows.map((row) => row.method)}`);
    for (const row of exact) assert.ok(row.bc_error < 1e-9 && row.E < 1e-6, `${patch} ${row.method}: bc ${row.bc_error}, E ${row.E}`);
  }
});

test('encode-link then decode-link gives bit-identical samples for every example', () => {
  const index = JSON.parse(readFileSync(join(root, 'examples/index.json'), 'utf8'));
  const dir = mkdtempSync(join(tmpdir(), 'pdesurf-link-'));
  for (const { id, file } of index.examples) {
    const enc = run('encode-link', join(root, 'examples', file));
    assert.equal(enc.status, 0, enc.stderr);
    const fragment = enc.stdout.trim();
    assert.match(fragment, /^s=1\.[A-Za-z0-9_-]+$/);
    const dec = run('decode-link', `http://localhost:8000/web/#${fragment}`);
    assert.equal(dec.status, 0, dec.stderr);
    const decoded = join(dir, `${id}.json`);
    writeFileSync(decoded, dec.stdout);
    const a = run('sample', join(root, 'examples', file), '--grid', '7x9');
    const b = run('sample', decoded, '--grid', '7x9');
    assert.equal(a.status, 0);
    assert.equal(b.stdout, a.stdout, `${id}: samples differ after the link round trip`);
  }
});

test('decode-link refuses hostile links by name, quickly', async () => {
  const { deflateRawSync } = await import('node:zlib');
  const b64url = (buf) => buf.toString('base64').replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
  const bomb = 's=1.' + b64url(deflateRawSync(Buffer.alloc(50 * 1024 * 1024, 32), { level: 9 }));
  const notJson = 's=1.' + b64url(deflateRawSync(Buffer.from('hello')));
  const noScene = 's=1.' + b64url(deflateRawSync(Buffer.from('{"grid": {"nu": 4}}')));
  const badScene = 's=1.' + b64url(deflateRawSync(Buffer.from('{"scene": {"format": "pdesurf-scene", "version": 2, "patches": []}}')));
  const cases = [
    ['s=9.AAAA', /unknown link version '9'/],
    ['s=1.ab$d', /bad base64/],
    ['s=1.' + run('encode-link', example('you2004-fig2a')).stdout.trim().slice(4, 40), /truncated/],
    [bomb, /inflates to more than 1048576 bytes/],
    [notJson, /not JSON/],
    [noScene, /holds no scene/],
    [badScene, /patches: expected a non-empty array/],
    ['#example=you2004-fig2a', /not a pdesurf link/],
  ];
  for (const [link, message] of cases) {
    const t0 = Date.now();
    const r = run('decode-link', link);
    assert.equal(r.status, 1, `${link.slice(0, 30)}: exit ${r.status}`);
    assert.match(r.stderr, message);
    assert.ok(Date.now() - t0 < 2000, 'fails fast');
  }
});

test('decode-link opens every stored link fixture the way the page does', () => {
  const fixtures = JSON.parse(readFileSync(join(root, 'tests/links/links.json'), 'utf8')).fixtures;
  const byKind = {
    format: /not a pdesurf link/, version: /unknown link version/, base64: /bad base64/, deflate: /broken|truncated/,
    size: /inflates to more than/, json: /not JSON|holds no scene/, scene: /holds no scene/,
  };
  assert.ok(fixtures.length >= 4);
  for (const f of fixtures) {
    const r = run('decode-link', f.link);
    if (f.expect) {
      assert.equal(r.status, 0, `${f.name}: ${r.stderr}`);
      const scene = JSON.parse(r.stdout);
      assert.equal(scene.title, f.expect.title, f.name);
      const values = Object.fromEntries(Object.entries(scene.parameters ?? {}).map(([k, p]) => [k, p.value]));
      assert.deepEqual(values, f.expect.parameters, f.name);
    } else {
      assert.equal(r.status, 1, `${f.name} must be refused`);
      assert.match(r.stderr, byKind[f.kind] ?? /./, `${f.name}: ${r.stderr}`);
    }
  }
});

test('Bezier patches: sample, export and --control-net', () => {
  const hat = example('wu2015-fig2');
  const net = run('sample', hat, '--control-net');
  assert.equal(net.status, 0, net.stderr);
  const rows = net.stdout.trim().split('\n');
  assert.equal(rows[0], 'i,j,x,y,z');
  assert.equal(rows.length - 1, 64, '8×8 control points');
  // The boundary ring is fixed: the first row is the initial net's, bit for bit.
  const scene = JSON.parse(readFileSync(hat, 'utf8'));
  const initial = scene.patches[0].control_net;
  rows.slice(1).forEach((line) => {
    const [i, j, x, y, z] = line.split(',').map(Number);
    if (i === 0 || j === 0 || i === 7 || j === 7) assert.deepEqual([x, y, z], initial[i * 8 + j]);
  });
  const surface = parseCsv(run('sample', hat, '--grid', '4x4').stdout);
  assert.equal(surface.length, 25);
  const pde = run('sample', example('you2004-fig2a'), '--control-net');
  assert.equal(pde.status, 1);
  assert.match(pde.stderr, /--control-net: the scene has no Bezier patch/);
  const named = run('sample', example('you2004-fig2a'), '--control-net', '--patch', 'blend');
  assert.equal(named.status, 1);
  assert.match(named.stderr, /patch 'blend' is not a Bezier patch/);
  // Without --patch, the first Bézier patch, not the first solved one (a chain before its plate).
  const net5 = [];
  for (let i = 0; i < 5; i++) for (let j = 0; j < 5; j++) net5.push([j / 4, i / 4, 0.1 * Math.sin(i) * Math.cos(j)]);
  const chained = { format: 'pdesurf-scene', version: 4, patches: [
    { name: 'ext', kind: 'pde', v_range: [0, 1], ends: { u0: { patch: 'plate', at: 'u1' } }, boundary: { x: { u1: ['v', 0] }, y: { u1: [2, 1] }, z: { u1: [0.2, 0] } } },
    { name: 'plate', kind: 'bezier', energy: 'thin-plate', degree: [4, 4], control_net: net5 }] };
  const file = join(mkdtempSync(join(tmpdir(), 'pdesurf-cli-')), 'chain-first.json');
  writeFileSync(file, JSON.stringify(chained));
  const last = run('sample', file, '--control-net');
  assert.equal(last.status, 0, last.stderr);
  assert.equal(last.stdout.trim().split('\n').length - 1, 25, 'the plate\'s 5×5 control points');

});

test('check: one line per join, exit 0 when every promise holds, 1 with the failing join named', () => {
  const ok = run('check', example('zhang-c2-ex1'));
  assert.equal(ok.status, 0, ok.stderr);
  const lines = ok.stdout.trim().split('\n');
  assert.equal(lines.filter((l) => l.startsWith('join ')).length, 2);
  assert.match(lines[0], /^join blend:u0 - cylinder:t0 {2}promise G2 .* ok$/);
  // The blend closes on itself around v: its seam is certified like a join, at its promise.
  assert.match(lines.find((l) => l.startsWith('seam ')), /^seam blend: v1 - v0 {2}promise G2 .* ok$/);
  assert.match(lines.at(-1), /^2 joins, 1 seam, 0 crossings: ok$/);

  const loop = run('check', example('you2004-fig1'), '--json');
  assert.equal(loop.status, 1);
  const report = JSON.parse(loop.stdout);
  assert.equal(report.ok, false);
  assert.ok(report.joins.every((j) => j.ok && j.g0 < 1e-9 && j.g1_deg < 1e-6 && j.g2_rel === null && !j.fold));
  assert.equal(report.crossings.length, 1);
  const [c] = report.crossings;
  assert.deepEqual([c.patch, c.other], ['blend', 'blend']);
  assert.ok(c.u[0] > 0.39 && c.u[1] < 0.44 && c.v[0] > 5.4 && c.v[1] < 6.3, JSON.stringify(c));

  const dir = mkdtempSync(join(tmpdir(), 'pdesurf-check-'));
  const scene = JSON.parse(readFileSync(example('you2004-fig2a'), 'utf8'));
  scene.patches[1].meets.patch = 'nowhere';
  writeFileSync(join(dir, 'bad.json'), JSON.stringify(scene));
  const bad = run('check', join(dir, 'bad.json'));
  assert.equal(bad.status, 1);
  assert.match(bad.stderr, /UnknownName: patches\[1\]\.meets\.patch: no pde or bezier patch named 'nowhere'/);
});
