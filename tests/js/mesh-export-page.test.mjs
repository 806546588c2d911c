// The page's mesh exports (web/export/mesh-export.js) from the wasm module's modelMesh, read
// back by real libraries: the aeroplane's and the bottle's bodies, as the page writes them in
// OBJ, STL, GLB (three's exporters) and 3MF (@jscadui/3mf-export, unzipped by fflate; and
// read by lib3mf, tests/mesh/read_3mf.cpp), are accepted by manifold-3d with the CLI's mesh volume; the wasm mesh is the CLI's (same
// vertices, same triangles); an open model is refused by manifold; names with markup stay
// text in 3MF's XML and on one line in OBJ.
//   PDESURF_CLI=build/native/pdesurf PDESURF_BUILD_DIR=build node --test tests/js/mesh-export-page.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { unzipSync, strFromU8 } from 'fflate';
import Module from 'manifold-3d';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { bodyMeshes, export3mf, exportGlb, exportObj, exportStl } from '../../web/export/mesh-export.js';
import { PdesurfError } from '../../web/solver/pdesurf-solver.js';
import { loadTestSolver } from './test-solver.mjs';

const root = new URL('../../', import.meta.url);
const solver = await loadTestSolver();
const cli = process.env.PDESURF_CLI ?? new URL('build/native/pdesurf', root).pathname;
const examplePath = (id) => new URL(`examples/${id}.json`, root).pathname;
const scene = (id) => readFileSync(examplePath(id), 'utf8');
const dir = mkdtempSync(join(tmpdir(), 'pdesurf-mesh-page-'));
// three's GLTFExporter reads its Blob with the browser's FileReader: the least of one for node.
globalThis.FileReader ??= class {
  readAsArrayBuffer(blob) {
    blob.arrayBuffer().then((b) => { this.result = b; this.onloadend?.(); });
  }
};
const manifold = await Module();
manifold.setup();

function toManifold(positions, triangles) {
  try {
    return new manifold.Manifold(new manifold.Mesh({ numProp: 3, vertProperties: positions, triVerts: triangles }));
  } catch (e) {
    return e;
  }
}

// Vertices the same where their float bits are (STL, and OBJ's text read back as floats).
function weld(points, corners) {
  const ids = new Map(), v = [], f = [];
  for (const c of corners) {
    const key = [0, 1, 2].map((d) => Math.fround(points[3 * c + d])).join();
    if (!ids.has(key)) ids.set(key, ids.size), v.push(...[0, 1, 2].map((d) => points[3 * c + d]));
    f.push(ids.get(key));
  }
  return { positions: new Float32Array(v), triangles: new Uint32Array(f) };
}

function readObj(text) {
  const v = [], f = [];
  for (const line of text.split('\n')) {
    const [kind, ...rest] = line.split(' ');
    if (kind === 'v') v.push(...rest.map(Number));
    else if (kind === 'f') f.push(...rest.map((c) => Number(c.split('/')[0]) - 1));
  }
  return { positions: new Float32Array(v), triangles: new Uint32Array(f) };
}

function readStl(buffer) {
  const view = new DataView(buffer);
  const n = view.getUint32(80, true), points = [];
  for (let t = 0; t < n; ++t) for (let k = 0; k < 9; ++k) points.push(view.getFloat32(84 + 50 * t + 12 + 4 * k, true));
  return weld(points, points.map((_, k) => k).filter((k) => k % 3 === 0).map((k) => k / 3));
}

// A body with several patches is a glTF mesh of several primitives over one vertex array:
// three's loader makes a mesh per primitive, sharing that array's attribute.
async function readGlb(buffer) {
  const gltf = await new Promise((resolve, reject) => new GLTFLoader().parse(buffer, '', resolve, reject));
  const bodies = new Map();
  gltf.scene.traverse((o) => {
    if (!o.isMesh) return;
    const position = o.geometry.attributes.position;
    if (!bodies.has(position)) bodies.set(position, { positions: position.array, triangles: [], primitives: 0, materials: [] });
    const b = bodies.get(position);
    b.triangles.push(...o.geometry.index.array);
    b.primitives += 1;
    b.materials.push(o.material.name);
  });
  return [...bodies.values()].map((b) => ({ ...b, triangles: new Uint32Array(b.triangles) }));
}

function read3mf(bytes) {
  const files = unzipSync(bytes);
  assert.ok(files['[Content_Types].xml'] && files['_rels/.rels'], Object.keys(files).join());
  const xml = strFromU8(files['3D/3dmodel.model']);
  const objects = [...xml.matchAll(/<object id="(\d+)" type="model"(?: name="([^"]*)")?>([\s\S]*?)<\/object>/g)].map(([, id, name, body]) => ({
    id,
    name,
    positions: new Float32Array([...body.matchAll(/<vertex x="([^"]+)" y="([^"]+)" z="([^"]+)"/g)].flatMap((m) => m.slice(1).map(Number))),
    triangles: new Uint32Array([...body.matchAll(/<triangle v1="(\d+)" v2="(\d+)" v3="(\d+)"/g)].flatMap((m) => m.slice(1).map(Number))),
  }));
  return { xml, objects };
}

for (const id of ['you2004-fig8d', 'bottle-solid']) {
  test(`${id}: the page's OBJ, STL, GLB and 3MF are each one manifold of the CLI's volume`, async () => {
    const model = solver.modelMesh(scene(id), { nu: 32, nv: 32 });
    assert.equal(model.bodies.length, 1);
    assert.ok(model.bodies[0].closed);
    // The CLI's mesh: the same vertices and triangles (the same core, the same floats).
    const out = join(dir, `${id}.obj`);
    assert.equal(spawnSync(cli, ['export', examplePath(id), '-o', out, '--grid', '32x32']).status, 0);
    const cliMesh = readObj(readFileSync(out, 'utf8'));
    const [body] = bodyMeshes(model);
    assert.equal(body.positions.length, cliMesh.positions.length);
    assert.equal(body.indices.length, cliMesh.triangles.length);
    const reference = toManifold(cliMesh.positions, cliMesh.triangles);
    assert.ok(reference instanceof manifold.Manifold, String(reference));
    const volume = reference.volume();
    const meshes = {
      obj: readObj(await exportObj(model)),
      stl: readStl(await exportStl(model)),
      '3mf': read3mf(await export3mf(model, id)).objects[0],
    };
    // lib3mf reads the page's package too and finds the body manifold and oriented.
    const threeMf = join(dir, `${id}.3mf`);
    writeFileSync(threeMf, await export3mf(model, id));
    const lib3mf = spawnSync(process.env.PDESURF_READ_3MF ?? join(dirname(cli), 'read_3mf'), [threeMf], { encoding: 'utf8' });
    assert.equal(lib3mf.status, 0, lib3mf.stderr);
    assert.deepEqual(JSON.parse(lib3mf.stdout).objects, [{ name: 'body 1', mesh: true, vertices: body.positions.length / 3, triangles: body.indices.length / 3, manifold: true }]);
    const [glb] = await readGlb(await exportGlb(model, new Map(), id));
    meshes.glb = glb;
    assert.equal(glb.primitives, model.parts.length, 'a primitive per patch');
    assert.deepEqual(glb.materials, model.parts.map((p) => p.name));
    for (const [format, m] of Object.entries(meshes)) {
      const mf = toManifold(m.positions, m.triangles);
      assert.ok(mf instanceof manifold.Manifold, `${format}: manifold-3d refused it: ${mf}`);
      assert.equal(mf.genus(), 0, format);
      assert.ok(Math.abs(mf.volume() - volume) <= 1e-6 * volume, `${format}: ${mf.volume()} against the CLI's ${volume}`);
    }
    console.log(`# ${id} at 32²: ${model.positions.length / 3} vertices, manifold volume ${volume.toFixed(6)}, exact ${model.bodies[0].volume.toFixed(6)}`);
  });
}

test('an open model\'s bodies are refused by manifold-3d (the check can fail), and said open', () => {
  const model = solver.modelMesh(scene('you2004-fig4a'), { nu: 16, nv: 16 });
  assert.deepEqual(model.bodies.map((b) => b.closed), [false]);
  const [body] = bodyMeshes(model);
  assert.ok(!(toManifold(body.positions, body.indices) instanceof manifold.Manifold));
});

test('names with markup stay text in 3MF, on one line in OBJ; bad grids are named errors', async () => {
  const s = JSON.parse(scene('bottle-solid'));
  const evil = 'a"<b>&\'c';
  const old = s.patches[0].name;
  s.patches[0].name = evil;
  const text = JSON.stringify(s).replaceAll(`"${old}"`, JSON.stringify(evil));
  const model = solver.modelMesh(text, { nu: 8, nv: 8 });
  assert.ok(model.parts.some((p) => p.name === evil));
  const { xml } = read3mf(await export3mf({ ...model, parts: [model.parts.find((p) => p.name === evil)] }, `<title>&`));
  assert.ok(xml.includes('name="a&quot;&lt;b&gt;&amp;&apos;c"'), xml.slice(0, 2000));
  assert.ok(xml.includes('&lt;title&gt;&amp;'));
  assert.ok(!xml.includes('<b>') && !xml.includes('<title>'));
  assert.throws(() => solver.modelMesh(scene('bottle-solid'), { nu: 2, nv: 8 }), (e) => e instanceof PdesurfError && e.code === 'GridSize' && /at least 3x3/.test(e.message));
  assert.throws(() => solver.modelMesh(scene('bottle-solid'), { nu: 8.5, nv: 8 }), (e) => e instanceof PdesurfError && e.code === 'GridSize');
  assert.throws(() => solver.modelMesh('{"format": 1}', { nu: 8, nv: 8 }), (e) => e instanceof PdesurfError);
});
