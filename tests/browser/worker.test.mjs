// The page never blocks (issue 10): solves run in a Web Worker. During a 30-step slider drag
// on a slow scene (pseudo-spectral:1000, about a second per solve in wasm) the page keeps
// painting, and the edit that waits cancels the running solve (the worker is restarted).
//   node --test tests/browser/worker.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { skip, startHarness, hooks, shoot, REPO } from './harness.mjs';
import { encodeState } from '../../web/link/link-codec.js';
// Frames painted, the longest gap between them and long tasks (requestAnimationFrame, Long Tasks API).
import { watchFrames } from './gizmo-drag.mjs';

const scene = JSON.parse(fs.readFileSync(path.join(REPO, 'examples', 'you2004-fig2a.json'), 'utf8'));

// copies: more blends like the first (each solved on its own), for a first solve that surely
// outlasts the cancel limit (one blend takes about 0.6 s in node, faster than it did).
async function linkTo(method, copies = 1) {
  const s = structuredClone(scene);
  s.patches[0].method = method;
  for (let c = 2; c <= copies; c++) s.patches.push({ ...structuredClone(s.patches[0]), name: `blend${c}` });
  return `/web/#${await encodeState({ scene: s, grid: { nu: 64, nv: 64 } })}`;
}

describe('solving off the main thread', { skip }, () => {
  let h;
  before(async () => {
    h = await startHarness();
  });
  after(async () => {
    await h?.close();
  });

  it('keeps painting through a 30-step drag on a slow scene', async () => {
    const page = await h.open(await linkTo('pseudo-spectral:1000'));
    const first = await hooks(page);
    assert.equal(first.lastError, null, first.lastError);
    await watchFrames(page);
    const box = await page.locator('#panel [data-param="r0"] .slider').boundingBox();
    const y = box.y + box.height / 2;
    await page.mouse.move(box.x + 10, y);
    await page.mouse.down();
    const t0 = Date.now();
    for (let k = 1; k <= 30; k++) {
      await page.mouse.move(box.x + 10 + 3 * k, y);
      await page.waitForTimeout(40);
    }
    await page.mouse.up();
    const dragMs = Date.now() - t0;
    const during = await page.evaluate(() => ({ ...window.__frames, restarts: window.__pdesurf.solverRestarts() }));
    await shoot(page, 'worker-drag.png');
    console.log(`# drag ${dragMs} ms: ${during.frames} frames, longest gap ${during.maxGap.toFixed(0)} ms, ` +
      `long tasks [${during.longTasks.join(', ')}] ms, worker restarts ${during.restarts}`);
    assert.ok(during.frames >= dragMs / 50, `only ${during.frames} frames in ${dragMs} ms`);
    assert.ok(during.maxGap < 250, `the page stopped painting for ${during.maxGap.toFixed(0)} ms`);
    assert.ok(during.longTasks.every((d) => d < 250), `long tasks ${during.longTasks}`);
    // The last edit is what ends up drawn.
    await page.waitForFunction(() => !document.getElementById('status').classList.contains('busy'), null, { timeout: 30_000 });
    const end = await hooks(page);
    assert.equal(end.lastError, null, end.lastError);
    assert.ok(end.solveCount > first.solveCount, 'no solve finished after the drag');
  });

  it('cancels a long solve when the next edit has waited past the limit', async () => {
    const page = await h.open(await linkTo('pseudo-spectral:1000', 3), { wait: false });
    // The first solve (three slow blends: about 1.6 s in node, more in the page) is running: move r0 now.
    await page.waitForFunction(() => document.getElementById('status').classList.contains('busy'), null, { timeout: 10_000 });
    await page.locator('#panel [data-param="r0"] input').first().fill('2.2');
    await page.waitForFunction(() => window.__pdesurf.ready, null, { timeout: 30_000 });
    const end = await hooks(page);
    assert.equal(end.lastError, null, end.lastError);
    assert.ok(await page.evaluate(() => window.__pdesurf.solverRestarts()) >= 1, 'the running solve was not cancelled');
    // Only the edit's solve was drawn: the cancelled one never arrives.
    assert.equal(end.solveCount, 1);
    assert.match(await page.evaluate(() => location.hash), /^#s=1\./);
  });

  it('says "solving…" with the elapsed time while a solve takes long', async () => {
    const page = await h.open(await linkTo('pseudo-spectral:1000'), { wait: false });
    await page.waitForFunction(() => /solving… \d+\.\d s/.test(document.getElementById('status').textContent), null, { timeout: 10_000 });
    await shoot(page, 'worker-busy.png');
    await page.waitForFunction(() => window.__pdesurf.ready, null, { timeout: 30_000 });
  });
});
