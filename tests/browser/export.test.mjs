// Exports from the page's "File" folder (web/features/files.js, web/export/): each download is
// caught and read back. The meshes are the model's watertight one (the worker's modelMesh),
// the CLI's own at the page's grid: OBJ one "o" per body, the CLI's vertices and faces;
// binary STL the CLI's triangles, 84 + 50 bytes each; GLB parsed by three's GLTFLoader in the
// page and by its chunks here, a node per body, a primitive per patch over one POSITION and
// NORMAL, faces wound with their normals, plain materials in the patch colours even while
// zebra shading is on; 3MF (the bottle) one object per body, accepted by manifold-3d; PNG: the drawing buffer
// times 1, 2 or 4, colours as on screen, a transparent one with alpha 0 off the surface;
// scene JSON: the page state, which the CLI reads to the same samples as the example file.
// The production page (/app/, when built) loads the exporters from its lazy chunks.
// DOM hooks: data-file="…" (web/ui/file-controls.js).
//   PDESURF_WASM_DIR=build/wasm node --test tests/browser/export.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { execFileSync } from 'node:child_process';
import { skip, startHarness, hooks, shoot, viewStats, solvedAfter, sameChecksum, OUT_DIR, ROOT, REPO, BACKGROUND } from './harness.mjs';
import { decodePng } from './png-decode.mjs';
import { blockAverage } from './image-diff.mjs';
import { unzipSync, strFromU8 } from 'fflate';
import Module from 'manifold-3d';

const CLI = process.env.PDESURF_CLI || path.join(ROOT, 'build', 'native', 'pdesurf');
const cli = fs.existsSync(CLI) ? CLI : null;
const exampleScene = (id) => JSON.parse(fs.readFileSync(path.join(ROOT, 'examples', `${id}.json`), 'utf8'));

/** Click a File-folder button and catch its download: { name, bytes (Buffer), ms }. */
export async function download(page, key) {
  const t0 = Date.now();
  const [d] = await Promise.all([
    page.waitForEvent('download', { timeout: 60_000 }),
    page.locator(`#panel [data-file="${key}"] button`).click(),
  ]);
  const bytes = fs.readFileSync(await d.path());
  return { name: d.suggestedFilename(), bytes, ms: Date.now() - t0 };
}

/** The CLI's watertight OBJ of an example at a grid: { bodies: 'o' names, v, f } counts. */
function cliMesh(id, nu, nv) {
  const out = path.join(OUT_DIR, `cli-${id}.obj`);
  execFileSync(CLI, ['export', path.join(ROOT, 'examples', `${id}.json`), '-o', out, '--grid', `${nu}x${nv}`]);
  const text = fs.readFileSync(out, 'utf8');
  return { v: (text.match(/^v /gm) || []).length, f: (text.match(/^f /gm) || []).length };
}

/** The bodies `check` finds, named as the page's exports name them (a lone patch's name, else "body N"). */
function cliBodies(id) {
  const { bodies } = JSON.parse(execFileSync(CLI, ['check', path.join(ROOT, 'examples', `${id}.json`), '--json'], { encoding: 'utf8' }));
  return bodies.map((b, k) => ({ name: b.patches.length === 1 ? b.patches[0] : `body ${k + 1}`, patches: b.patches, closed: b.closed }));
}

/** GLB -> { json, bin } (checked: magic, version, chunk lengths). */
function readGlb(buf) {
  assert.equal(buf.toString('latin1', 0, 4), 'glTF');
  assert.equal(buf.readUInt32LE(4), 2, 'glTF version');
  assert.equal(buf.readUInt32LE(8), buf.length, 'GLB length field');
  const jsonLen = buf.readUInt32LE(12);
  assert.equal(buf.readUInt32LE(16), 0x4e4f534a, 'first chunk is JSON');
  const json = JSON.parse(buf.toString('utf8', 20, 20 + jsonLen));
  const binStart = 20 + jsonLen;
  assert.equal(buf.readUInt32LE(binStart + 4), 0x004e4942, 'second chunk is BIN');
  const bin = buf.subarray(binStart + 8, binStart + 8 + buf.readUInt32LE(binStart));
  return { json, bin };
}

/** The typed array behind a glTF accessor (tightly packed, as three's exporter writes). */
function accessorArray({ json, bin }, index) {
  const acc = json.accessors[index];
  const view = json.bufferViews[acc.bufferView];
  const size = { SCALAR: 1, VEC2: 2, VEC3: 3 }[acc.type];
  const Type = { 5126: Float32Array, 5125: Uint32Array, 5123: Uint16Array }[acc.componentType];
  const offset = bin.byteOffset + (view.byteOffset || 0) + (acc.byteOffset || 0);
  const copy = new Uint8Array(acc.count * size * Type.BYTES_PER_ELEMENT);
  copy.set(new Uint8Array(bin.buffer, offset, copy.length));
  return new Type(copy.buffer);
}

/** Share of triangles whose winding normal points along their vertices' mean normal. */
function windingAgreement(pos, nrm, idx) {
  let agree = 0, counted = 0;
  for (let t = 0; t < idx.length; t += 3) {
    const [a, b, c] = [idx[t], idx[t + 1], idx[t + 2]];
    const e1 = [0, 1, 2].map((k) => pos[3 * b + k] - pos[3 * a + k]);
    const e2 = [0, 1, 2].map((k) => pos[3 * c + k] - pos[3 * a + k]);
    const n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
    const len = Math.hypot(...n);
    if (len < 1e-12) continue; // a collapsed triangle (a pole) has no winding
    const m = [0, 1, 2].map((k) => nrm[3 * a + k] + nrm[3 * b + k] + nrm[3 * c + k]);
    counted++;
    if (n[0] * m[0] + n[1] * m[1] + n[2] * m[2] > 0) agree++;
  }
  return agree / counted;
}

describe('exports from the page', { skip }, () => {
  let h, page;
  const figures = [];

  async function mesh() {
    return page.evaluate(() => ({ ...window.__pdesurf.lastSolve, vertices: window.__pdesurf.vertexCount() }));
  }
  async function openExample(id) {
    const before = await hooks(page);
    if (before.exampleId === id && (await page.evaluate(() => location.hash)) === `#example=${id}`) return before;
    await page.evaluate((x) => { location.hash = `#example=${x}`; }, id);
    const now = await solvedAfter(page, before.solveCount);
    assert.equal(now.exampleId, id);
    assert.equal(now.lastError, null);
    return now;
  }

  before(async () => {
    h = await startHarness();
    await h.context.addInitScript(() => {
      window.__cspViolations = [];
      document.addEventListener('securitypolicyviolation', (e) => window.__cspViolations.push(`${e.violatedDirective}: ${e.blockedURI}`));
    });
    page = await h.open('/web/#example=you2004-fig2a');
    assert.equal((await hooks(page)).lastError, null);
  });
  after(async () => {
    if (figures.length) console.log(`# exports: ${figures.join('; ')}`);
    await h?.close();
  });

  it('has a File folder right after Share with every action', async () => {
    const titles = await page.locator('#panel > .children > .lil-gui > .title').allTextContents();
    const share = titles.indexOf('Share');
    assert.ok(share >= 0, titles.join(', '));
    assert.equal(titles[share + 1], 'File', titles.join(', '));
    await page.locator('#panel [data-folder="file"] > .title').click();
    // lil-gui animates the opening: wait for it to end.
    await page.waitForFunction(() => !document.querySelector('#panel [data-folder="file"]').matches('.closed, .transition'));
    for (const key of ['open', 'json', 'obj', 'stl', 'glb', '3mf', 'png']) {
      assert.ok(await page.locator(`#panel [data-file="${key}"] button`).isVisible(), key);
    }
    assert.deepEqual(await page.locator('#panel [data-file="png-scale"] option').allTextContents(), ['1×', '2×', '4×']);
    assert.equal(await page.locator('[data-file="input"]').count(), 1);
    await page.locator('#panel [data-folder="file"]').scrollIntoViewIfNeeded();
    await shoot(page, 'file-folder.png');
  });

  for (const id of ['you2004-fig2a', 'wu2015-fig3']) {
    it(`${id}: OBJ has the model's bodies, the CLI's vertices and faces`, async () => {
      await openExample(id);
      const m = await mesh();
      const obj = await download(page, 'obj');
      assert.equal(obj.name, `${id}.obj`);
      const text = obj.bytes.toString('utf8');
      const count = (re) => (text.match(re) || []).length;
      const want = cliMesh(id, m.nu, m.nv);
      assert.equal(count(/^v /gm), want.v, 'v lines');
      assert.equal(count(/^vn /gm), want.v, 'vn lines');
      assert.equal(count(/^f /gm), want.f, 'f lines');
      assert.deepEqual([...text.matchAll(/^o (.*)$/gm)].map((x) => x[1]), cliBodies(id).map((b) => b.name.replace(/\s+/g, '_')), 'blanks as _ on an o line');
      assert.equal(count(/^usemtl /gm), 0, 'usemtl without an .mtl file');
      figures.push(`${id} OBJ ${(obj.bytes.length / 1024).toFixed(0)} KiB`);
    });

    it(`${id}: binary STL has the CLI's triangles`, async () => {
      const m = await mesh();
      const stl = await download(page, 'stl');
      assert.equal(stl.name, `${id}.stl`);
      const n = stl.bytes.readUInt32LE(80);
      assert.equal(n, cliMesh(id, m.nu, m.nv).f);
      assert.equal(stl.bytes.length, 84 + 50 * n);
      figures.push(`${id} STL ${(stl.bytes.length / 1024).toFixed(0)} KiB`);
    });

    it(`${id}: GLB has a node per body, a primitive per patch with POSITION, NORMAL, indices, wound with its normals`, async () => {
      const bodies = cliBodies(id);
      const m = await mesh();
      const glb = await download(page, 'glb');
      assert.equal(glb.name, `${id}.glb`);
      const doc = readGlb(glb.bytes);
      const { json } = doc;
      assert.deepEqual(json.nodes.map((n) => n.name), bodies.map((b) => b.name));
      assert.deepEqual(json.scenes[json.scene ?? 0].nodes.length, bodies.length);
      const want = cliMesh(id, m.nu, m.nv);
      let vertices = 0, triangles = 0;
      for (const [k, node] of json.nodes.entries()) {
        const prims = json.meshes[node.mesh].primitives;
        assert.equal(prims.length, bodies[k].patches.length, 'a primitive per patch');
        assert.deepEqual(prims.map((p) => json.materials[p.material].name), bodies[k].patches);
        const { attributes } = prims[0];
        vertices += json.accessors[attributes.POSITION].count;
        assert.equal(json.accessors[attributes.NORMAL].count, json.accessors[attributes.POSITION].count, `${node.name} NORMAL`);
        for (const { attributes: a, indices, mode } of prims) {
          assert.ok(mode === undefined || mode === 4, 'triangles');
          assert.equal(a.POSITION, attributes.POSITION, 'the patches share the body\'s vertices');
          triangles += json.accessors[indices].count / 3;
          const agree = windingAgreement(accessorArray(doc, a.POSITION), accessorArray(doc, a.NORMAL), accessorArray(doc, indices));
          assert.ok(agree > 0.99, `${node.name}: ${(100 * agree).toFixed(1)} % of the faces are wound with their normals`);
        }
      }
      assert.equal(vertices, want.v);
      assert.equal(triangles, want.f);
      // Read back by three's own loader, in the page.
      const loaded = await page.evaluate(async (b64) => {
        const { GLTFLoader } = await import('three/addons/loaders/GLTFLoader.js');
        const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
        const gltf = await new GLTFLoader().parseAsync(bytes.buffer, '');
        const meshes = [];
        gltf.scene.traverse((o) => {
          if (!o.isMesh) return;
          const position = o.geometry.getAttribute('position');
          meshes.push({ first: !meshes.some((m) => m.position === position), position, vertices: position.count, normals: Boolean(o.geometry.getAttribute('normal')), type: o.material.type });
        });
        return meshes.map(({ position, ...m }) => m);
      }, glb.bytes.toString('base64'));
      // A mesh of several primitives loads as a group of meshes, one per patch, over its vertices.
      assert.equal(loaded.length, bodies.reduce((n, b) => n + b.patches.length, 0));
      assert.equal(loaded.reduce((n, x) => n + (x.first ? x.vertices : 0), 0), want.v);
      for (const x of loaded) {
        assert.ok(x.normals);
        assert.equal(x.type, 'MeshStandardMaterial');
      }
      figures.push(`${id} GLB ${(glb.bytes.length / 1024).toFixed(0)} KiB`);
    });
  }

  it('3MF of the bottle: one object, a closed manifold (manifold-3d) with the exact volume to the mesh\'s accuracy', async () => {
    await openExample('bottle-solid');
    const m = await mesh();
    const file = await download(page, '3mf');
    assert.equal(file.name, 'bottle-solid.3mf');
    const files = unzipSync(new Uint8Array(file.bytes));
    assert.ok(files['[Content_Types].xml'] && files['_rels/.rels']);
    const xml = strFromU8(files['3D/3dmodel.model']);
    const objects = [...xml.matchAll(/<object id="\d+" type="model" name="([^"]*)">([\s\S]*?)<\/object>/g)];
    assert.deepEqual(objects.map((o) => o[1]), ['body 1']);
    const body = objects[0][2];
    const positions = new Float32Array([...body.matchAll(/<vertex x="([^"]+)" y="([^"]+)" z="([^"]+)"/g)].flatMap((x) => x.slice(1).map(Number)));
    const triangles = new Uint32Array([...body.matchAll(/<triangle v1="(\d+)" v2="(\d+)" v3="(\d+)"/g)].flatMap((x) => x.slice(1).map(Number)));
    const want = cliMesh('bottle-solid', m.nu, m.nv);
    assert.equal(positions.length / 3, want.v);
    assert.equal(triangles.length / 3, want.f);
    const wasm = await Module();
    wasm.setup();
    const solid = new wasm.Manifold(new wasm.Mesh({ numProp: 3, vertProperties: positions, triVerts: triangles }));
    assert.equal(solid.genus(), 0);
    assert.ok(cliBodies('bottle-solid')[0].closed);
    const { bodies } = JSON.parse(execFileSync(CLI, ['check', path.join(ROOT, 'examples', 'bottle-solid.json'), '--json'], { encoding: 'utf8' }));
    // The mesh's own error at the page's grid: O(h²), 0.16 % at 64².
    assert.ok(Math.abs(solid.volume() - bodies[0].volume) < 4e-3 * bodies[0].volume, `${solid.volume()} against ${bodies[0].volume}`);
    await page.waitForFunction(() => /^saved bottle-solid\.3mf \(\d+ KiB\)$/.test(document.querySelector('#status').textContent));
    figures.push(`bottle 3MF ${(file.bytes.length / 1024).toFixed(0)} KiB, manifold volume ${solid.volume().toFixed(5)} (exact ${bodies[0].volume.toFixed(5)})`);
  });

  it('GLB materials are the patch colours even while zebra shading is on', async () => {
    await openExample('you2004-fig2a');
    const plain = readGlb((await download(page, 'glb')).bytes).json.materials;
    await page.locator('#panel [data-folder="analysis"] > .title').click();
    await page.locator('#panel [data-analysis="shading"] select').selectOption('zebra stripes');
    await page.waitForFunction(() => window.__pdesurf.analysis()?.mode === 'zebra');
    const zebra = readGlb((await download(page, 'glb')).bytes).json.materials;
    assert.deepEqual(zebra, plain);
    assert.deepEqual(plain.map((x) => x.name).sort(), exampleScene('you2004-fig2a').patches.map((p) => p.name).sort(), 'a material per patch');
    for (const x of plain) {
      assert.equal(x.doubleSided, true);
      assert.equal(x.extensions, undefined, 'a shader leaked into the file');
      assert.equal(x.pbrMetallicRoughness.baseColorFactor.length, 4);
    }
    await page.locator('#panel [data-analysis="shading"] select').selectOption('normal');
    await page.waitForFunction(() => window.__pdesurf.analysis()?.mode === 'normal');
    await page.locator('#panel [data-folder="analysis"] > .title').click();
  });

  it('PNG at 1× is the drawing buffer, coloured as on screen, and leaves the view alone', async () => {
    const buffer = await page.evaluate(() => { const c = document.querySelector('#viewport canvas'); return { w: c.width, h: c.height }; });
    const before = await hooks(page);
    const png = await download(page, 'png');
    assert.equal(png.name, 'you2004-fig2a.png');
    const img = decodePng(png.bytes);
    fs.writeFileSync(path.join(OUT_DIR, 'export-view.png'), png.bytes);
    assert.deepEqual([img.width, img.height], [buffer.w, buffer.h]);
    // Same colours as the canvas on screen (a linear, unencoded read-back would be far darker).
    const shot = decodePng(await page.locator('#viewport canvas').screenshot());
    assert.deepEqual([shot.width, shot.height], [img.width, img.height]);
    const rect = { x0: 0, y0: 60, x1: img.width, y1: img.height - 60 }; // off the title and status lines
    const a = blockAverage(img, rect, 8).rgb, b = blockAverage(shot, rect, 8).rgb;
    let diff = 0;
    for (let k = 0; k < a.length; k++) diff += Math.abs(a[k] - b[k]);
    diff /= a.length;
    assert.ok(diff < 4, `mean |Δ| ${diff.toFixed(2)} per channel between the PNG and the screen`);
    // The corner is the page's background, opaque.
    assert.deepEqual([...img.data.subarray(0, 3)], BACKGROUND);
    if (img.channels === 4) assert.equal(img.data[3], 255);
    const after = await hooks(page);
    assert.ok(sameChecksum(after.checksum, before.checksum));
    assert.deepEqual(after.camera, before.camera);
    assert.deepEqual(await page.evaluate(() => { const c = document.querySelector('#viewport canvas'); return { w: c.width, h: c.height }; }), buffer);
    const stats = await viewStats(page, await shoot(page, 'export-after-png.png'));
    assert.ok(stats.fraction > 0.03, `the view looks blank after the export: ${JSON.stringify(stats)}`);
    figures.push(`PNG 1× ${img.width}×${img.height} ${(png.bytes.length / 1024).toFixed(0)} KiB in ${png.ms} ms`);
  });

  for (const [label, scale] of [['2×', 2], ['4×', 4]]) {
    it(`PNG at ${label} is ${scale} times the drawing buffer`, async () => {
      const buffer = await page.evaluate(() => { const c = document.querySelector('#viewport canvas'); return { w: c.width, h: c.height }; });
      await page.locator('#panel [data-file="png-scale"] select').selectOption(label);
      const png = await download(page, 'png');
      assert.equal(png.name, `you2004-fig2a@${scale}x.png`);
      const img = decodePng(png.bytes);
      assert.deepEqual([img.width, img.height], [buffer.w * scale, buffer.h * scale]);
      fs.writeFileSync(path.join(OUT_DIR, `export-view@${scale}x.png`), png.bytes);
      figures.push(`PNG ${label} ${img.width}×${img.height} ${(png.bytes.length / 1024).toFixed(0)} KiB in ${png.ms} ms`);
    });
  }

  it('PNG with a transparent background: alpha 0 off the surface, opaque on it', async () => {
    await page.locator('#panel [data-file="png-scale"] select').selectOption('1×');
    await page.locator('#panel [data-file="png-transparent"] input').check();
    const png = await download(page, 'png');
    const img = decodePng(png.bytes);
    fs.writeFileSync(path.join(OUT_DIR, 'export-view-transparent.png'), png.bytes);
    assert.equal(img.channels, 4, 'no alpha channel');
    let opaque = 0, clear = 0;
    for (let k = 3; k < img.data.length; k += 4) {
      if (img.data[k] === 255) opaque++;
      else if (img.data[k] === 0) clear++;
    }
    const n = img.width * img.height;
    assert.equal(img.data[3], 0, 'the corner is not transparent');
    assert.ok(opaque / n > 0.03, `${opaque} opaque pixels of ${n}`);
    assert.ok(clear / n > 0.3, `${clear} transparent pixels of ${n}`);
    // The surface keeps its colours: an opaque pixel far from any edge looks like the 1× PNG.
    const plain = decodePng(fs.readFileSync(path.join(OUT_DIR, 'export-view.png')));
    let same = 0, checked = 0;
    for (let k = 0; k < n; k += 97) {
      if (img.data[4 * k + 3] !== 255) continue;
      checked++;
      const d = [0, 1, 2].reduce((s, c) => s + Math.abs(img.data[4 * k + c] - plain.data[plain.channels * k + c]), 0);
      if (d <= 6) same++;
    }
    assert.ok(same / checked > 0.95, `${same} of ${checked} surface pixels keep their colour`);
    await page.locator('#panel [data-file="png-transparent"] input').uncheck();
  });

  it('scene JSON is the page state; the CLI reads it to the same samples as the example', async (t) => {
    const json = await download(page, 'json');
    assert.equal(json.name, 'you2004-fig2a.json');
    const text = json.bytes.toString('utf8');
    assert.match(text, /^\{\n {2}"/, 'pretty-printed');
    const scene = JSON.parse(text);
    assert.deepEqual(scene, exampleScene('you2004-fig2a'));
    const file = path.join(OUT_DIR, json.name);
    fs.writeFileSync(file, json.bytes);
    if (!cli) {
      t.skip(`no CLI at ${CLI} (set PDESURF_CLI): only the page's own read-back (import.test.mjs) checks the file`);
      return;
    }
    const sample = (f) => execFileSync(cli, ['sample', f, '--grid', '16x16'], { encoding: 'utf8' });
    assert.equal(sample(file), sample(path.join(ROOT, 'examples', 'you2004-fig2a.json')));
  });

  it('an edited scene is exported as edited, named after its example', async () => {
    const before = await hooks(page);
    await page.locator('#panel [data-expr="patches[0].boundary.x.u0[1]"] input').fill('r0p*cos(v)*1.2');
    const edited = await solvedAfter(page, before.solveCount);
    assert.equal(edited.lastError, null);
    const json = await download(page, 'json');
    assert.equal(json.name, 'you2004-fig2a.json');
    assert.equal(JSON.parse(json.bytes.toString('utf8')).patches[0].boundary.x.u0[1], 'r0p*cos(v)*1.2');
  });

  it('a scene with no example id is named after its title', async () => {
    const text = JSON.stringify({ ...exampleScene('you2004-fig2a'), title: 'Cône & plane: <b> = 1' });
    const before = await hooks(page);
    await page.locator('[data-file="input"]').setInputFiles({ name: 'mine.json', mimeType: 'application/json', buffer: Buffer.from(text) });
    const opened = await solvedAfter(page, before.solveCount);
    assert.equal(opened.exampleId, null);
    assert.equal((await download(page, 'obj')).name, 'cone-plane-b-1.obj');
    await page.locator('#panel [data-file="png-scale"] select').selectOption('2×');
    assert.equal((await download(page, 'png')).name, 'cone-plane-b-1@2x.png');
  });

  it('the production page (/app/) loads the exporters from its chunks', { skip: !fs.existsSync(path.join(REPO, 'build', 'web', 'index.html')) && 'no build/web' }, async () => {
    const app = await h.open('/app/#example=wu2015-fig3');
    await app.locator('#panel [data-folder="file"] > .title').click();
    const m = await app.evaluate(() => ({ ...window.__pdesurf.lastSolve }));
    for (const [key, check] of [
      ['glb', (b) => assert.deepEqual(readGlb(b).json.nodes.map((n) => n.name), ['hat'])],
      ['stl', (b) => assert.equal(b.readUInt32LE(80), 2 * m.nu * m.nv)], // one open patch: its grid's triangles
      ['3mf', (b) => assert.match(strFromU8(unzipSync(new Uint8Array(b))['3D/3dmodel.model']), /<object id="1" type="model" name="hat">/)],
      ['png', (b) => assert.ok(decodePng(b).width > 0)],
    ]) {
      const [d] = await Promise.all([app.waitForEvent('download', { timeout: 60_000 }), app.locator(`#panel [data-file="${key}"] button`).click()]);
      assert.equal(d.suggestedFilename(), `wu2015-fig3.${key}`);
      check(fs.readFileSync(await d.path()));
    }
    assert.deepEqual(await app.evaluate(() => window.__cspViolations), []);
    await app.close();
  });

  it('logged no console error, page error, failed request or CSP violation', async () => {
    assert.deepEqual(await page.evaluate(() => window.__cspViolations), []);
    assert.deepEqual(h.problems, []);
  });
});
