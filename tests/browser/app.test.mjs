// The production page (scripts/build-web.mjs, served as /app/): bundled, minified, served
// compressed, and it works like the sources (no console error, no CSP violation). Prints the
// cold start (navigation to the first surface, cache disabled, median of 5) and the bytes on
// the wire; scripts/bench reports the same figures.
//   node scripts/build-web.mjs && node --test tests/browser/app.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { skip, startHarness, hooks, shoot, coldStart, REPO } from './harness.mjs';

const built = fs.existsSync(path.join(REPO, 'build', 'web', 'index.html'));

describe('the production page', { skip: skip || (!built && 'no build/web: run node scripts/build-web.mjs') }, () => {
  let h;
  before(async () => {
    h = await startHarness();
  });
  after(async () => {
    await h?.close();
  });

  it('draws the default example like the sources do, with no error or CSP violation', async () => {
    const app = await h.open('/app/#example=you2004-fig2a');
    const a = await hooks(app);
    assert.equal(a.lastError, null, a.lastError);
    await shoot(app, 'app-1280.png');
    const web = await h.open('/web/#example=you2004-fig2a');
    const w = await hooks(web);
    assert.equal(a.vertexCount, w.vertexCount);
    assert.ok(Math.abs(a.checksum - w.checksum) <= 1e-9 * Math.abs(w.checksum), 'the bundle draws something else');
    assert.deepEqual(h.problems, []);
  });

  it('is sent compressed, small, and starts cold in well under a second', async () => {
    const runs = [];
    for (let k = 0; k < 5; k++) runs.push(await coldStart(h, `${h.base}/app/#example=you2004-fig2a`));
    for (const r of runs) assert.equal(r.state.lastError, null, r.state.lastError);
    const e = runs[0].encodings;
    for (const p of ['/app/main.js', '/app/solver-worker.js', '/wasm/pdesurf.wasm', '/wasm/pdesurf.js']) assert.equal(e[p], 'br', `${p}: ${e[p]}`);
    const ms = runs.map((r) => r.ms).sort((x, y) => x - y);
    const bytes = runs[0].bytes;
    console.log(`# cold start /app/: median ${ms[2].toFixed(0)} ms (${ms.map((x) => x.toFixed(0)).join(', ')}), ${(bytes / 1024).toFixed(0)} KiB on the wire`);
    assert.ok(bytes < 1 << 20, `${bytes} bytes on the wire`);
    assert.ok(ms[2] < 3000, `median cold start ${ms[2]} ms`); // the target (500 ms) is a benchmark figure, not a test
  });
});
