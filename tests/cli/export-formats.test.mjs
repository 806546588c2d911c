// pdesurf export --patches (each patch its own grid) in every format (obj, stl, ply, glb) and
// sample's number text: each file read back byte for byte and compared with the others and with
// sample's doubles. The joined (watertight) meshes: watertight-export.test.mjs.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';

const root = new URL('../../', import.meta.url).pathname;
const cli = process.env.PDESURF_CLI ?? join(root, 'build/native/pdesurf');
const example = (id) => join(root, 'examples', `${id}.json`);
const run = (...args) => spawnSync(cli, args, { encoding: 'utf8', maxBuffer: 1 << 28 });
const dir = mkdtempSync(join(tmpdir(), 'pdesurf-formats-'));
const NU = 6, NV = 5; // not square: rows and columns cannot be confused
const VERTICES = (NU + 1) * (NV + 1), TRIANGLES = 2 * NU * NV;
const PATCHES = ['blend', 'cylinder', 'plane']; // you2004-fig4a

function exportAs(file, ...extra) {
  const out = join(dir, file);
  const r = run('export', example('you2004-fig4a'), '-o', out, '--grid', `${NU}x${NV}`, '--patches', ...extra);
  assert.equal(r.status, 0, r.stderr);
  const b = readFileSync(out);
  return { bytes: b, view: new DataView(b.buffer, b.byteOffset, b.byteLength) };
}

// The significant digits of a number's text: "-0.00125" and "1.25e-3" both give "125".
const digits = (s) => s.replace(/^-/, '').replace(/e.*$/i, '').replace('.', '').replace(/^0+/, '').replace(/0+$/, '');
// The fewest significant digits whose nearest decimal reads back as the same float.
function floatDigits(f) {
  for (let p = 1; p <= 9; ++p) if (Math.fround(Number(f.toPrecision(p))) === f) return p;
  return 9;
}

function parseObj(text) {
  const objects = [];
  let o = null;
  for (const line of text.split('\n')) {
    const [kind, ...rest] = line.split(' ');
    if (kind === 'o') objects.push((o = { name: rest.join(' '), v: [], vt: [], vn: [], f: [] }));
    else if (kind === 'v' || kind === 'vt' || kind === 'vn') o[kind].push(rest);
    else if (kind === 'f') {
      o.f.push(rest.map((corner) => {
        const [a, b, c] = corner.split('/').map(Number);
        assert.ok(a === b && b === c, `f corner ${corner}: v/vt/vn indices agree`);
        return a;
      }));
    }
  }
  return objects;
}

const obj = parseObj(exportAs('fig4a.obj').bytes.toString('utf8'));
// The float values every binary format must hold: the OBJ's text read as a float.
const f32 = (texts) => texts.map((t) => Math.fround(Number(t)));

test('OBJ: floats in shortest round-trip form, equal to sample\'s doubles rounded to float', () => {
  assert.deepEqual(obj.map((o) => o.name), PATCHES);
  obj.forEach((o, k) => {
    assert.equal(o.v.length, VERTICES);
    assert.equal(o.vt.length, VERTICES);
    assert.equal(o.vn.length, VERTICES);
    assert.equal(o.f.length, TRIANGLES);
    const base = k * VERTICES + 1; // 1-based, global across objects
    for (const tri of o.f) assert.ok(tri.every((i) => i >= base && i < base + VERTICES), `${o.name}: ${tri}`);
    for (const t of [...o.v, ...o.vn].flat()) {
      const f = Math.fround(Number(t));
      assert.ok(digits(t).length <= floatDigits(f), `${t} is not the shortest text of the float ${f}`);
    }
    o.vt.forEach(([u, v], idx) => {
      assert.equal(Math.fround(Number(u)), Math.fround((idx % (NU + 1)) / NU));
      assert.equal(Math.fround(Number(v)), Math.fround(Math.floor(idx / (NU + 1)) / NV));
    });
    const sample = run('sample', example('you2004-fig4a'), '--patch', o.name, '--grid', `${NU}x${NV}`);
    assert.equal(sample.status, 0, sample.stderr);
    const rows = sample.stdout.trim().split('\n').slice(1).map((l) => l.split(','));
    assert.equal(rows.length, VERTICES);
    rows.forEach((row, idx) => {
      assert.deepEqual(f32(o.v[idx]), row.slice(2).map((t) => Math.fround(Number(t))), `${o.name} vertex ${idx}`);
    });
  });
});

test('sample: doubles in shortest round-trip form (the digits JavaScript prints)', () => {
  const r = run('sample', example('you2004-fig4a'), '--grid', '7x9');
  assert.equal(r.status, 0, r.stderr);
  const [header, ...lines] = r.stdout.trim().split('\n');
  assert.equal(header, 'u,v,x,y,z');
  assert.equal(lines.length, 8 * 10);
  for (const line of lines)
    for (const t of line.split(',')) assert.equal(digits(t), digits(String(Number(t))), `${t} in ${line}`);
  const net = run('sample', example('wu2015-fig2'), '--control-net');
  for (const line of net.stdout.trim().split('\n').slice(1)) {
    const [i, j, ...xyz] = line.split(',');
    assert.match(`${i},${j}`, /^\d+,\d+$/);
    for (const t of xyz) assert.equal(digits(t), digits(String(Number(t))), t);
  }
});

test('STL: 84 + 50 bytes per triangle, unit facet normals by the right-hand rule, the OBJ\'s vertices', () => {
  const { bytes, view } = exportAs('fig4a.stl');
  const header = bytes.subarray(0, 80).toString('latin1');
  assert.ok(!header.startsWith('solid'), 'an ASCII-looking header would confuse readers');
  assert.match(header, /^pdesurf export: Cylinder blended/);
  const count = view.getUint32(80, true);
  assert.equal(count, PATCHES.length * TRIANGLES);
  assert.equal(bytes.length, 84 + 50 * count);
  const v = obj.flatMap((o) => o.v.map(f32));
  const faces = obj.flatMap((o) => o.f);
  for (let t = 0; t < count; ++t) {
    const at = 84 + 50 * t;
    const n = [0, 1, 2].map((d) => view.getFloat32(at + 4 * d, true));
    const p = [0, 1, 2].map((c) => [0, 1, 2].map((d) => view.getFloat32(at + 12 + 12 * c + 4 * d, true)));
    assert.deepEqual(p, faces[t].map((i) => v[i - 1]), `triangle ${t}`);
    assert.equal(view.getUint16(at + 48, true), 0);
    assert.ok(Math.abs(Math.hypot(...n) - 1) < 1e-6, `triangle ${t}: |n| = ${Math.hypot(...n)}`);
    const e1 = p[1].map((x, d) => x - p[0][d]), e2 = p[2].map((x, d) => x - p[0][d]);
    const cross = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
    const cosine = (cross[0] * n[0] + cross[1] * n[1] + cross[2] * n[2]) / Math.hypot(...cross);
    assert.ok(cosine > 1 - 1e-6, `triangle ${t}: the normal ${n} is not (b - a) × (c - a) = ${cross} of ${p.join(" ")}`);
  }
});

test('PLY: binary little-endian header and counts, the OBJ\'s positions, normals and faces', () => {
  const { bytes, view } = exportAs('fig4a.ply');
  const end = bytes.indexOf('end_header\n') + 'end_header\n'.length;
  const header = bytes.subarray(0, end).toString('utf8').trim().split('\n');
  assert.deepEqual(header.filter((l) => !l.startsWith('comment')), [
    'ply', 'format binary_little_endian 1.0', `element vertex ${3 * VERTICES}`,
    'property float x', 'property float y', 'property float z', 'property float nx', 'property float ny', 'property float nz',
    `element face ${3 * TRIANGLES}`, 'property list uchar uint vertex_indices', 'end_header',
  ]);
  assert.deepEqual(header.filter((l) => l.startsWith('comment patch ')), PATCHES.map((p) => `comment patch ${p} faces ${TRIANGLES}`));
  assert.equal(bytes.length, end + 3 * VERTICES * 24 + 3 * TRIANGLES * 13);
  const expected = obj.flatMap((o) => o.v.map((xyz, k) => [...f32(xyz), ...f32(o.vn[k])]));
  expected.forEach((want, k) => {
    const got = [0, 1, 2, 3, 4, 5].map((d) => view.getFloat32(end + 24 * k + 4 * d, true));
    assert.deepEqual(got, want, `vertex ${k}`);
  });
  const faceStart = end + 3 * VERTICES * 24;
  obj.flatMap((o) => o.f).forEach((tri, t) => {
    const at = faceStart + 13 * t;
    assert.equal(view.getUint8(at), 3);
    assert.deepEqual([0, 1, 2].map((c) => view.getUint32(at + 1 + 4 * c, true)), tri.map((i) => i - 1));
  });
});

function readGlb({ bytes, view }) {
  assert.equal(bytes.subarray(0, 4).toString('latin1'), 'glTF');
  assert.equal(view.getUint32(4, true), 2);
  assert.equal(view.getUint32(8, true), bytes.length);
  const jsonLength = view.getUint32(12, true);
  assert.equal(view.getUint32(16, true), 0x4e4f534a, 'JSON chunk');
  assert.equal(jsonLength % 4, 0);
  const text = bytes.subarray(20, 20 + jsonLength).toString('utf8');
  assert.match(text, /^\{.*\} *$/s, 'padded with spaces');
  const binLength = view.getUint32(20 + jsonLength, true);
  assert.equal(view.getUint32(24 + jsonLength, true), 0x004e4942, 'BIN chunk');
  assert.equal(binLength % 4, 0);
  assert.equal(28 + jsonLength + binLength, bytes.length);
  return { gltf: JSON.parse(text), bin: 28 + jsonLength, binLength };
}

test('GLB: header, chunks, one named mesh per patch over the model\'s vertices, accessors consistent with the binary chunk', () => {
  const file = exportAs('fig4a.glb');
  const { view } = file;
  const { gltf, bin, binLength } = readGlb(file);
  assert.equal(gltf.asset.version, '2.0');
  assert.equal(gltf.buffers.length, 1);
  assert.equal(gltf.buffers[0].byteLength, binLength);
  assert.deepEqual(gltf.nodes.map((n) => n.name), PATCHES);
  assert.deepEqual(gltf.scenes[gltf.scene].nodes, [0, 1, 2]);
  const SIZE = { SCALAR: 1, VEC2: 2, VEC3: 3 };
  const read = (index) => {
    const a = gltf.accessors[index];
    const bv = gltf.bufferViews[a.bufferView];
    assert.equal(bv.byteOffset % 4, 0);
    assert.ok(bv.byteOffset + bv.byteLength <= binLength);
    assert.equal(a.byteOffset ?? 0, 0);
    assert.equal(bv.byteLength, 4 * SIZE[a.type] * a.count, 'tightly packed');
    const get = a.componentType === 5126 ? (at) => view.getFloat32(at, true) : (at) => view.getUint32(at, true);
    assert.ok(a.componentType === 5126 || a.componentType === 5125);
    const values = [];
    for (let k = 0; k < a.count; ++k) values.push([...Array(SIZE[a.type]).keys()].map((d) => get(bin + bv.byteOffset + 4 * (SIZE[a.type] * k + d))));
    return { a, values };
  };
  gltf.nodes.forEach((node, k) => {
    const o = obj[k];
    const [primitive] = gltf.meshes[node.mesh].primitives;
    assert.equal(primitive.mode ?? 4, 4);
    const position = read(primitive.attributes.POSITION);
    const normal = read(primitive.attributes.NORMAL);
    const uv = read(primitive.attributes.TEXCOORD_0);
    const indices = read(primitive.indices);
    // One POSITION, NORMAL and TEXCOORD_0 for the model; each patch's indices into them.
    assert.equal(position.a.count, PATCHES.length * VERTICES);
    assert.deepEqual(position.values, obj.flatMap((x) => x.v.map(f32)));
    assert.deepEqual(normal.values, obj.flatMap((x) => x.vn.map(f32)));
    // glTF's texture origin is the top left, OBJ's the bottom left: TEXCOORD_0 = (u, 1 - v).
    assert.deepEqual(uv.values, obj.flatMap((x) => x.vt.map(([u, v]) => [Math.fround(Number(u)), Math.fround(1 - Math.fround(Number(v)))])));
    assert.deepEqual(indices.values.flat(), o.f.flat().map((i) => i - 1));
    for (let d = 0; d < 3; ++d) {
      const column = position.values.map((p) => p[d]);
      assert.equal(position.a.min[d], Math.min(...column), `${node.name} min[${d}]`);
      assert.equal(position.a.max[d], Math.max(...column), `${node.name} max[${d}]`);
    }
  });
});

test('GLB: three.js GLTFLoader reads it in node', async () => {
  const { bytes } = exportAs('loader.glb');
  const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  const gltf = await new Promise((resolve, reject) => new GLTFLoader().parse(buffer, '', resolve, reject));
  const meshes = gltf.scene.children;
  assert.deepEqual(meshes.map((m) => m.name), PATCHES);
  meshes.forEach((m, k) => {
    const g = m.geometry;
    assert.equal(g.attributes.position.count, PATCHES.length * VERTICES);
    assert.equal(g.index.count, 3 * TRIANGLES);
    assert.deepEqual(Array.from(g.attributes.position.array), obj.flatMap((x) => x.v.flatMap(f32)));
    assert.deepEqual(Array.from(g.index.array), obj[k].f.flat().map((i) => i - 1));
  });
});

test('export: the format from --format, else the extension (any case), else obj; unknown formats refused by name', () => {
  assert.equal(exportAs('upper.STL').bytes.length, 84 + 50 * 3 * TRIANGLES);
  assert.equal(exportAs('x.dat').bytes.subarray(0, 17).toString(), '# pdesurf export:');
  assert.equal(exportAs('x.obj', '--format', 'glb').bytes.subarray(0, 4).toString(), 'glTF');
  assert.equal(exportAs('noext', '--format', 'ply').bytes.subarray(0, 4).toString(), 'ply\n');
  const out = join(dir, 'never.x');
  const bad = run('export', example('you2004-fig4a'), '-o', out, '--format', 'dxf');
  assert.equal(bad.status, 1);
  assert.match(bad.stderr, /unknown --format 'dxf': expected obj, stl, ply, glb, 3mf, step, stp, iges or igs/);
  assert.ok(!existsSync(out), 'refused before writing anything');
  const misplaced = run('sample', example('you2004-fig4a'), '--format', 'stl');
  assert.equal(misplaced.status, 1);
  assert.match(misplaced.stderr, /--format applies to export only/);
});

test('STL: a zero-area triangle at a pole gets the normal (0, 0, 0), every other one a unit normal', () => {
  const out = join(dir, 'poles.stl');
  const r = run('export', example('you2004-fig6'), '-o', out, '--grid', '8x8');
  assert.equal(r.status, 0, r.stderr);
  const b = readFileSync(out);
  const view = new DataView(b.buffer, b.byteOffset, b.byteLength);
  const count = view.getUint32(80, true);
  assert.equal(b.length, 84 + 50 * count);
  let zero = 0;
  for (let t = 0; t < count; ++t) {
    const at = 84 + 50 * t;
    const len = Math.hypot(...[0, 1, 2].map((d) => view.getFloat32(at + 4 * d, true)));
    const p = [0, 1, 2].map((c) => [0, 1, 2].map((d) => view.getFloat32(at + 12 + 12 * c + 4 * d, true)).join());
    const degenerate = p[0] === p[1] || p[1] === p[2] || p[0] === p[2];
    if (len === 0) zero++;
    assert.ok(degenerate ? len === 0 : Math.abs(len - 1) < 1e-6, `triangle ${t}: |n| = ${len}`);
  }
  console.log(`# you2004-fig6 at 8x8: ${zero} of ${count} triangles have zero area`);
});
