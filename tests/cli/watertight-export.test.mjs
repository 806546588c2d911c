// pdesurf export's meshes are watertight (issue 36): the patches share their vertices along
// every join, so a closed model's OBJ, STL, PLY and GLB are each a manifold mesh, judged by a
// real library (manifold-3d accepts only manifold, oriented meshes), whose volume agrees with
// `check`'s exact one (Richardson over two grids); the loose --patches meshes and open models
// are refused by it, so the check can fail.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import Module from 'manifold-3d';

const root = new URL('../../', import.meta.url).pathname;
const cli = process.env.PDESURF_CLI ?? join(root, 'build/native/pdesurf');
const example = (id) => join(root, 'examples', `${id}.json`);
const run = (...args) => spawnSync(cli, args, { encoding: 'utf8', maxBuffer: 1 << 28 });
const dir = mkdtempSync(join(tmpdir(), 'pdesurf-watertight-'));
// Under AddressSanitizer (the sanitize row) the aeroplane's solve is ten times slower: the
// bottle and a few small examples there; natively everything.
const sanitized = process.env.PDESURF_CLI_SANITIZED === '1';
const manifold = await Module();
manifold.setup();

function exportFile(id, ext, grid, ...extra) {
  const out = join(dir, `${id}-${grid}${extra.join('')}.${ext}`);
  const r = run('export', example(id), '-o', out, '--grid', `${grid}x${grid}`, ...extra);
  assert.equal(r.status, 0, r.stderr);
  return readFileSync(out);
}

// Each reader gives { positions: Float32Array, triangles: Uint32Array } as the file has them.
function readObj(bytes) {
  const v = [], f = [];
  for (const line of bytes.toString('utf8').split('\n')) {
    const [kind, ...rest] = line.split(' ');
    if (kind === 'v') v.push(...rest.map(Number));
    else if (kind === 'f') f.push(...rest.map((corner) => Number(corner.split('/')[0]) - 1));
  }
  return { positions: new Float32Array(v), triangles: new Uint32Array(f) };
}

// STL has no indices: vertices are the same where their float bits are.
function readStl(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const count = view.getUint32(80, true);
  const ids = new Map(), v = [], f = [];
  for (let t = 0; t < count; ++t)
    for (let c = 0; c < 3; ++c) {
      const at = 84 + 50 * t + 12 + 12 * c;
      const key = bytes.subarray(at, at + 12).toString('hex');
      if (!ids.has(key)) {
        ids.set(key, ids.size);
        for (let d = 0; d < 3; ++d) v.push(view.getFloat32(at + 4 * d, true));
      }
      f.push(ids.get(key));
    }
  return { positions: new Float32Array(v), triangles: new Uint32Array(f) };
}

function readPly(bytes) {
  const end = bytes.indexOf('end_header\n') + 'end_header\n'.length;
  const header = bytes.subarray(0, end).toString('utf8');
  const vertices = Number(/element vertex (\d+)/.exec(header)[1]), faces = Number(/element face (\d+)/.exec(header)[1]);
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const v = new Float32Array(3 * vertices), f = new Uint32Array(3 * faces);
  for (let k = 0; k < vertices; ++k) for (let d = 0; d < 3; ++d) v[3 * k + d] = view.getFloat32(end + 24 * k + 4 * d, true);
  const start = end + 24 * vertices;
  for (let t = 0; t < faces; ++t) {
    assert.equal(view.getUint8(start + 13 * t), 3);
    for (let c = 0; c < 3; ++c) f[3 * t + c] = view.getUint32(start + 13 * t + 1 + 4 * c, true);
  }
  return { positions: v, triangles: f };
}

function readGlb(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const jsonLength = view.getUint32(12, true);
  const gltf = JSON.parse(bytes.subarray(20, 20 + jsonLength).toString('utf8'));
  const bin = 28 + jsonLength;
  const read = (index, Type) => {
    const a = gltf.accessors[index], bv = gltf.bufferViews[a.bufferView];
    const size = { SCALAR: 1, VEC3: 3 }[a.type];
    return new Type(bytes.buffer.slice(bytes.byteOffset + bin + bv.byteOffset, bytes.byteOffset + bin + bv.byteOffset + 4 * size * a.count));
  };
  const primitives = gltf.meshes.map((m) => m.primitives[0]);
  const position = primitives[0].attributes.POSITION;
  assert.ok(primitives.every((p) => p.attributes.POSITION === position), 'the patches share one vertex array');
  const f = primitives.flatMap((p) => Array.from(read(p.indices, Uint32Array)));
  return { positions: read(position, Float32Array), triangles: new Uint32Array(f) };
}

const READERS = { obj: readObj, stl: readStl, ply: readPly, glb: readGlb };

// Edges used once (free), a directed edge used twice (faces turned apart), edges on three or more.
function edgeCounts({ triangles }) {
  const directed = new Map();
  for (let t = 0; t < triangles.length; t += 3)
    for (let c = 0; c < 3; ++c) {
      const key = `${triangles[t + c]},${triangles[t + (c + 1) % 3]}`;
      directed.set(key, (directed.get(key) ?? 0) + 1);
    }
  let free = 0, turned = 0, overused = 0;
  for (const [key, n] of directed) {
    const [a, b] = key.split(',');
    const back = directed.get(`${b},${a}`) ?? 0;
    turned += n > 1;
    if (back === 0 || Number(a) < Number(b)) free += n + back === 1, overused += n + back > 2;
  }
  return { free, turned, overused };
}

// manifold-3d's verdict: the Manifold, or the error it throws for a mesh that is not one.
function toManifold({ positions, triangles }) {
  const mesh = new manifold.Mesh({ numProp: 3, vertProperties: positions, triVerts: triangles });
  try {
    return new manifold.Manifold(mesh);
  } catch (e) {
    return e;
  }
}

function bodiesOf(id) {
  const r = run('check', example(id), '--json');
  return JSON.parse(r.stdout).bodies;
}

for (const id of sanitized ? ['bottle-solid'] : ['you2004-fig8d', 'bottle-solid']) {
  test(`${id}: every mesh format one closed manifold of genus 0, its volume the exact one (Richardson 32/64) within 1e-4`, () => {
    const [body] = bodiesOf(id);
    assert.ok(body.closed);
    const volume = {};
    for (const grid of [32, 64]) {
      const volumes = Object.entries(READERS).map(([ext, read]) => {
        const mesh = read(exportFile(id, ext, grid));
        assert.deepEqual(edgeCounts(mesh), { free: 0, turned: 0, overused: 0 }, `${ext} at ${grid}`);
        const m = toManifold(mesh);
        assert.ok(m instanceof manifold.Manifold, `${ext} at ${grid}: manifold-3d refused it: ${m}`);
        assert.equal(m.status(), 'NoError');
        assert.equal(m.genus(), 0);
        assert.ok(m.volume() > 0, 'outward');
        return m.volume();
      });
      // The same float vertices in every format: the same volume to rounding.
      for (const v of volumes) assert.ok(Math.abs(v - volumes[0]) <= 1e-9 * volumes[0], `${volumes}`);
      volume[grid] = volumes[0];
    }
    const richardson = (4 * volume[64] - volume[32]) / 3;
    console.log(`# ${id}: manifold-3d volume ${volume[32]} (32²), ${volume[64]} (64²), Richardson ${richardson}; check ${body.volume}`);
    assert.ok(Math.abs(richardson - body.volume) <= 1e-4 * body.volume, `${richardson} against ${body.volume}`);
  });
}

test('the loose --patches mesh of a closed model is refused by manifold-3d (the check can fail)', () => {
  const m = toManifold(readObj(exportFile(sanitized ? 'bottle-solid' : 'you2004-fig8d', 'obj', 16, '--patches')));
  assert.ok(!(m instanceof manifold.Manifold), 'each patch its own vertices: not one closed mesh');
});

test('every example: manifold and one-way along every join; closed exactly when check says every body is', () => {
  const index = JSON.parse(readFileSync(join(root, 'examples/index.json'), 'utf8'));
  const ids = sanitized ? ['you2004-fig4a', 'wu2015-fig1a', 'you2004-fig8c', 'bottle-solid', 'zhang-vase-fig1a'] : index.examples.map((e) => e.id);
  let closedModels = 0;
  for (const id of ids) {
    const mesh = readObj(exportFile(id, 'obj', 8));
    const counts = edgeCounts(mesh);
    assert.equal(counts.turned, 0, `${id}: two faces turned apart across an edge`);
    assert.equal(counts.overused, 0, `${id}: an edge on three faces`);
    const allClosed = bodiesOf(id).every((b) => b.closed);
    assert.equal(counts.free === 0, allClosed, `${id}: ${counts.free} free edges, bodies closed: ${allClosed}`);
    assert.equal(toManifold(mesh) instanceof manifold.Manifold, allClosed, `${id}: manifold-3d's verdict`);
    closedModels += allClosed;
  }
  assert.ok(closedModels >= (sanitized ? 1 : 2));
});

test('a watertight mesh needs a row inside each patch: 2x2 refused by name, --patches takes it', () => {
  const out = join(dir, 'small.obj');
  const r = run('export', example('you2004-fig4a'), '-o', out, '--grid', '2x2');
  assert.equal(r.status, 1);
  assert.match(r.stderr, /a watertight mesh needs at least 3x3 cells a patch/);
  assert.equal(run('export', example('you2004-fig4a'), '-o', out, '--grid', '2x2', '--patches').status, 0);
  assert.match(run('check', example('you2004-fig4a'), '--patches').stderr, /--patches applies to export only/);
});

// lib3mf's own reader and manifold check (tests/mesh/read_3mf.cpp), beside the CLI.
const read3mf = (file) => {
  const r = spawnSync(process.env.PDESURF_READ_3MF ?? join(dirname(cli), 'read_3mf'), [file], { encoding: 'utf8' });
  assert.equal(r.status, 0, r.stderr);
  return JSON.parse(r.stdout).objects;
};

test('3MF (lib3mf): the aeroplane and the bottle one manifold, oriented object each; open or loose meshes are not', () => {
  for (const id of sanitized ? ['bottle-solid'] : ['you2004-fig8d', 'bottle-solid']) {
    const file = join(dir, `${id}.3mf`);
    assert.equal(run('export', example(id), '-o', file, '--grid', '16x16').status, 0);
    const objects = read3mf(file);
    const obj = readObj(exportFile(id, 'obj', 16));
    assert.deepEqual(objects, [{ name: 'body 1', mesh: true, vertices: obj.positions.length / 3, triangles: obj.triangles.length / 3, manifold: true }]);
  }
  const loose = join(dir, 'loose.3mf');
  assert.equal(run('export', example('bottle-solid'), '-o', loose, '--grid', '16x16', '--patches').status, 0);
  assert.equal(read3mf(loose)[0].manifold, false, 'each patch its own vertices');
  const open = join(dir, 'open.3mf');
  assert.equal(run('export', example('you2004-fig4a'), '-o', open, '--grid', '16x16').status, 0);
  assert.deepEqual(read3mf(open).map((o) => [o.name, o.manifold]), [['body 1', false]]);
});
