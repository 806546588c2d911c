// The bundle (scripts/build-web.mjs) carries rhino3dm for the .3dm writer: its ES module and
// wasm copied unchanged to build/web/rhino3dm/ with their precompressed siblings, the writer's
// worker pointing there, nothing else naming rhino3dm's files, and the worker itself named
// only by the lazy chunk of the File folder's 3dm export (web/cad/export-3dm.js), which the
// page does not load at start.
//   node scripts/build-web.mjs && node --test tests/js/build-web-rhino3dm.test.mjs
import { describe, it } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { fileURLToPath } from 'node:url';

const REPO = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const APP = process.env.PDESURF_APP_DIR || path.join(REPO, 'build', 'web');
const built = fs.existsSync(path.join(APP, 'index.html'));

describe('rhino3dm in the bundle', { skip: !built && `no ${APP}: run node scripts/build-web.mjs` }, () => {
  it('is copied unchanged, precompressed, to rhino3dm/', () => {
    for (const f of ['rhino3dm.module.min.js', 'rhino3dm.wasm']) {
      const copy = fs.readFileSync(path.join(APP, 'rhino3dm', f));
      assert.ok(copy.equals(fs.readFileSync(path.join(REPO, 'node_modules', 'rhino3dm', f))), `${f} differs from the package's`);
      assert.ok(zlib.brotliDecompressSync(fs.readFileSync(path.join(APP, 'rhino3dm', `${f}.br`))).equals(copy), `${f}.br`);
      assert.ok(zlib.gunzipSync(fs.readFileSync(path.join(APP, 'rhino3dm', `${f}.gz`))).equals(copy), `${f}.gz`);
    }
  });

  it('is what the writer\'s worker imports, and nothing else of the bundle names it', () => {
    assert.match(fs.readFileSync(path.join(APP, 'rhino-worker.js'), 'utf8'), /new URL\("\.\/rhino3dm\/rhino3dm\.module\.min\.js",import\.meta\.url\)/);
    const others = fs.readdirSync(APP).filter((f) => /\.(js|html)$/.test(f) && f !== 'rhino-worker.js');
    assert.ok(others.includes('main.js') && others.includes('index.html'));
    const read = (f) => fs.readFileSync(path.join(APP, f), 'utf8');
    // (The panel's own words may say "Rhino": its files are what must not be named.)
    for (const f of others) assert.ok(!/rhino3dm\/|rhino3dm\.(module\.)?(min\.)?(js|wasm)/i.test(read(f)), `${f} names rhino3dm's files`);
    // The worker is started from one chunk, which neither the page's HTML nor main.js loads.
    const starters = others.filter((f) => read(f).includes('new URL("./rhino-worker.js",import.meta.url)'));
    assert.equal(starters.length, 1, `chunks starting the worker: ${starters}`);
    assert.match(starters[0], /^chunk-/);
    const start = read('index.html') + read('main.js');
    assert.ok(!start.includes(starters[0]), `${starters[0]} is loaded at start`);
  });
});
