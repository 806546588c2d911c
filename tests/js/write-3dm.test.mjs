// web/cad/write-3dm.js: fitted B-spline surfaces written to .3dm through rhino3dm and read
// back with it: names, degrees, openNURBS's knots (no superfluous end knots), poles, the
// model's tolerance and units, and the surfaces themselves, compared pointwise with an
// independent de Boor evaluator (de-boor.mjs), which a perturbed pole must fail. rhino3dm is
// loaded on first use only.
//   node --test tests/js/write-3dm.test.mjs
import { describe, it, before } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { write3dm } from '../../web/cad/write-3dm.js';
import { loadRhino3dm } from '../../web/cad/load-rhino3dm.js';
import { evaluate } from './de-boor.mjs';
import { samples, random } from './bspline-samples.mjs';

const TOLERANCE = 0.01;
const REL = 1e-9;

/** The largest |rhino - de Boor| at 50 random (u, v), over the size of the poles. */
function relativeError(srf, s, rnd) {
  const scale = Math.max(...s.poles.map(Math.abs));
  let worst = 0;
  for (let k = 0; k < 50; k++) {
    const u = s.knotsU[0] + rnd() * (s.knotsU.at(-1) - s.knotsU[0]);
    const v = s.knotsV[0] + rnd() * (s.knotsV.at(-1) - s.knotsV[0]);
    const p = srf.pointAt(u, v), q = evaluate(s, u, v);
    worst = Math.max(worst, Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]) / scale);
  }
  return worst;
}

/** The file's surfaces as [{ name, srf }] (rhino3dm objects; the caller deletes `file`). */
function surfacesOf(file) {
  const out = [];
  const objects = file.objects();
  for (let k = 0; k < objects.count; k++) {
    const o = objects.get(k);
    out.push({ name: o.attributes().name, deviation: o.attributes().getUserString('pdesurf.deviation'), srf: o.geometry() });
  }
  return out;
}

describe('write3dm', () => {
  let rh, given, file, read;
  before(async () => {
    given = samples();
    const bytes = await write3dm(given, { tolerance: TOLERANCE, title: 'four samples' });
    assert.ok(bytes instanceof Uint8Array && bytes.length > 1000);
    rh = await loadRhino3dm();
    file = rh.File3dm.fromByteArray(bytes);
    assert.ok(file, 'rhino3dm cannot read the file back');
    read = surfacesOf(file);
  });

  it('writes the model in millimetres with the given tolerance and title', () => {
    const settings = file.settings();
    assert.equal(settings.modelAbsoluteTolerance, TOLERANCE);
    assert.equal(settings.modelUnitSystem, rh.UnitSystem.Millimeters);
    assert.equal(file.strings().getvalue('title'), 'four samples');
  });

  it('writes one named non-rational NurbsSurface per surface', () => {
    assert.equal(read.length, given.length);
    assert.deepEqual(read.map((r) => r.name), given.map((s) => s.name));
    for (const [k, { srf, deviation }] of read.entries()) {
      const s = given[k];
      assert.equal(srf.constructor.name, 'NurbsSurface', s.name);
      assert.equal(srf.isRational, false, s.name);
      assert.deepEqual([srf.degree(0), srf.degree(1)], [s.degreeU, s.degreeV], s.name);
      assert.deepEqual([srf.points().countU, srf.points().countV], [s.countU, s.countV], s.name);
      assert.equal(Number(deviation), s.deviation, s.name);
    }
  });

  it('keeps openNURBS knots: the full clamped vectors less their first and last knot', () => {
    for (const [k, { srf }] of read.entries()) {
      const s = given[k];
      assert.deepEqual(srf.knotsU().toList(), s.knotsU.slice(1, -1), s.name);
      assert.deepEqual(srf.knotsV().toList(), s.knotsV.slice(1, -1), s.name);
      assert.equal(srf.knotsU().count, s.countU + s.degreeU - 1, s.name);
      // So the surface's domain is the patch's own parameter range.
      assert.deepEqual(srf.domain(0), [s.knotsU[0], s.knotsU.at(-1)], s.name);
      assert.deepEqual(srf.domain(1), [s.knotsV[0], s.knotsV.at(-1)], s.name);
    }
  });

  it('reads the seam and the collapsed border as openNURBS sees them', () => {
    const byName = Object.fromEntries(read.map((r) => [r.name, r.srf]));
    assert.equal(byName.tube.isClosed(1), true);
    assert.equal(byName['open cubic'].isClosed(1), false);
    // openNURBS sides: 0 v=v0, 1 u=u1, 2 v=v1, 3 u=u0.
    assert.deepEqual([0, 1, 2, 3].map((side) => byName.apex.isSingular(side)), [false, false, false, true]);
  });

  it('evaluates to the given surfaces (de Boor) at 50 random (u, v) each, to 1e-9', () => {
    const rnd = random(42);
    for (const [k, { srf }] of read.entries()) {
      const e = relativeError(srf, given[k], rnd);
      assert.ok(e <= REL, `${given[k].name}: relative error ${e}`);
    }
  });

  it('fails that comparison when a pole is moved before writing', async () => {
    const moved = samples();
    const s = moved[1];
    s.poles[(4 * s.countV + 5) * 3 + 2] += 1e-6 * Math.max(...s.poles.map(Math.abs)); // one inner pole's z
    const back = rh.File3dm.fromByteArray(await write3dm([s], { tolerance: TOLERANCE }));
    try {
      const e = relativeError(surfacesOf(back)[0].srf, given[1], random(42));
      assert.ok(e > 10 * REL, `a moved pole went unnoticed: relative error ${e}`);
    } finally {
      back.delete();
    }
  });

  it('refuses bad input before loading rhino3dm', async () => {
    const loadRhino = () => assert.fail('rhino3dm loaded for bad input');
    const [s] = samples();
    await assert.rejects(write3dm([s], { tolerance: 0, loadRhino }), /tolerance/);
    await assert.rejects(write3dm([{ ...s, knotsU: s.knotsU.slice(1) }], { tolerance: 1, loadRhino }), /knotsU has/);
    await assert.rejects(write3dm([{ ...s, knotsV: [s.knotsV[0] - 1, ...s.knotsV.slice(1)] }], { tolerance: 1, loadRhino }), /knotsV not clamped/);
    await assert.rejects(write3dm([{ ...s, poles: s.poles.map((x, k) => (k === 7 ? NaN : x)) }], { tolerance: 1, loadRhino }), /pole coordinate 7/);
  });
});

describe('the rhino3dm loader', () => {
  it('is lazy: importing write-3dm.js loads no rhino3dm; the first write does', () => {
    // A fresh node whose resolve hook reports every module URL: rhino3dm must not be among
    // them after the import, and must be after a write (the hook sees it then, so it would
    // have seen it before).
    const child = `
      import { register } from 'node:module';
      const { port1, port2 } = new MessageChannel();
      const urls = [];
      port1.on('message', (u) => urls.push(u));
      port1.unref();
      register('data:text/javascript,' + encodeURIComponent(
        'let port; export function initialize(d) { port = d.port; }' +
        'export async function resolve(s, c, next) { const r = await next(s, c); port.postMessage(r.url); return r; }'),
        { data: { port: port2 }, transferList: [port2] });
      const settle = () => new Promise((r) => setTimeout(r, 100));
      const { write3dm } = await import(${JSON.stringify(new URL('../../web/cad/write-3dm.js', import.meta.url).href)});
      await settle();
      const before = urls.filter((u) => u.includes('/node_modules/rhino3dm/')).length;
      const { samples } = await import(${JSON.stringify(new URL('./bspline-samples.mjs', import.meta.url).href)});
      await write3dm(samples().slice(0, 1), { tolerance: 1 });
      await settle();
      console.log(JSON.stringify({ imported: urls.some((u) => u.endsWith('write-3dm.js')), before, after: urls.filter((u) => u.includes('/node_modules/rhino3dm/')).length }));
    `;
    const r = spawnSync(process.execPath, ['--input-type=module', '-e', child], {
      cwd: fileURLToPath(new URL('../..', import.meta.url)), encoding: 'utf8', timeout: 60_000,
    });
    assert.equal(r.status, 0, r.stderr.slice(0, 2000));
    const seen = JSON.parse(r.stdout.trim().split('\n').at(-1));
    assert.equal(seen.imported, true, 'the hook saw no module');
    assert.equal(seen.before, 0, 'rhino3dm was loaded by the import');
    assert.ok(seen.after > 0, 'the write did not load rhino3dm (or the hook cannot see it)');
  });

  it('starts rhino3dm once', async () => {
    assert.equal(loadRhino3dm(), loadRhino3dm());
    assert.equal(await loadRhino3dm(), await loadRhino3dm());
  });
});
