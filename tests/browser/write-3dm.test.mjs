// The .3dm writer in the page (web/cad/export-3dm.js, rhino-worker.js): nothing of rhino3dm
// is fetched at page load; the first export starts the worker, which loads rhino3dm under a
// policy of its own (rhino3dm's glue needs eval, which the page's CSP refuses) and hands back
// a file rhino3dm reads back in node, with no CSP violation on the page. The sources (/web/)
// and, when built, the bundle (/app/: build/web or $PDESURF_APP_DIR).
//   PDESURF_WASM_DIR=build/wasm node --test tests/browser/write-3dm.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { skip, startHarness, recordRequestsAndCsp, REPO } from './harness.mjs';
import { loadRhino3dm } from '../../web/cad/load-rhino3dm.js';
import { samples } from '../js/bspline-samples.mjs';
import { evaluate } from '../js/de-boor.mjs';

const APP = process.env.PDESURF_APP_DIR || path.join(REPO, 'build', 'web');
const built = fs.existsSync(path.join(APP, 'rhino-worker.js'));
const SURFACES = samples().map((s) => ({ ...s, poles: Array.from(s.poles) })); // as page.evaluate passes them

// Bytes from the page read back: the sample surfaces, by name, at their parameter midpoints.
async function checkFile(bytes) {
  const rh = await loadRhino3dm();
  const file = rh.File3dm.fromByteArray(Uint8Array.from(bytes));
  try {
    const objects = file.objects();
    assert.equal(objects.count, SURFACES.length);
    for (let k = 0; k < objects.count; k++) {
      const s = SURFACES[k], o = objects.get(k);
      assert.equal(o.attributes().name, s.name);
      const u = (s.knotsU[0] + s.knotsU.at(-1)) / 2, v = (s.knotsV[0] + s.knotsV.at(-1)) / 2;
      const p = o.geometry().pointAt(u, v), q = evaluate(s, u, v);
      assert.ok(Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]) <= 1e-9 * Math.max(...s.poles.map(Math.abs)), s.name);
    }
    assert.equal(file.settings().modelAbsoluteTolerance, 0.01);
  } finally {
    file.delete();
  }
}

describe('the .3dm writer in the page', { skip }, () => {
  let h;
  let requests = [];
  before(async () => {
    h = await startHarness();
    requests = await recordRequestsAndCsp(h);
  });
  after(async () => {
    await h?.close();
  });

  const rhinoRequests = () => requests.filter((p) => /rhino/i.test(p));

  it('sources: fetch no rhino3dm at load; the first export writes the file in its worker', async () => {
    requests.length = 0;
    const page = await h.open('/web/');
    assert.deepEqual(rhinoRequests(), [], 'rhino3dm fetched at page load');
    const bytes = await page.evaluate(async (surfaces) => {
      const { export3dm } = await import('/web/cad/export-3dm.js');
      const file = await export3dm(surfaces.map((s) => ({ ...s, poles: Float64Array.from(s.poles) })), { tolerance: 0.01, title: 't' });
      return Array.from(file);
    }, SURFACES);
    await checkFile(bytes);
    assert.ok(rhinoRequests().includes('/node_modules/rhino3dm/rhino3dm.wasm'), `rhino3dm requests: ${rhinoRequests()}`);
    assert.deepEqual(await page.evaluate(() => window.__cspViolations), []);
    assert.deepEqual(h.problems, []);
    await page.close();
  });

  it('bundle: fetches no rhino3dm at load; /app/rhino-worker.js writes the file', { skip: !built && `no ${APP}/rhino-worker.js: run node scripts/build-web.mjs` }, async () => {
    requests.length = 0;
    const page = await h.open('/app/');
    assert.deepEqual(rhinoRequests(), [], 'rhino3dm fetched at page load');
    const reply = await page.evaluate((surfaces) => new Promise((resolve) => {
      const worker = new Worker('/app/rhino-worker.js', { type: 'module' });
      worker.onmessage = ({ data }) => resolve(data.error ? { error: data.error } : { bytes: Array.from(data.bytes) });
      worker.onerror = () => resolve({ error: 'the worker did not load' });
      worker.postMessage({ id: 1, surfaces, tolerance: 0.01, title: 't' });
    }), SURFACES);
    assert.equal(reply.error, undefined, reply.error);
    await checkFile(reply.bytes);
    assert.ok(rhinoRequests().includes('/app/rhino3dm/rhino3dm.wasm'), `rhino3dm requests: ${rhinoRequests()}`);
    assert.deepEqual(await page.evaluate(() => window.__cspViolations), []);
    assert.deepEqual(h.problems, []);
    await page.close();
  });
});
