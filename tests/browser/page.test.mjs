// End-to-end test of the modeller page in headless Chromium (Debian's, through
// playwright-core): the page draws, sliders re-solve, solver errors are shown while
// the last good surfaces stay, operator orders and methods can be chosen, links open
// examples, and nothing logs an error. Controls are found by their data-* hooks:
// data-param="<name>", data-operator="<axis>.<coefficient>", data-order="<axis>",
// data-method / data-method-used="<patch>" (web/ui/*-controls.js).
//   node --test tests/browser/
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { startServer } from '../../scripts/static-server.mjs';
import { decodePng, pixelStats } from './png-decode.mjs';

const REPO = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
// Another site root (with examples/, web/, node_modules/) can be tested in place of the repo.
const ROOT = process.env.PDESURF_TEST_ROOT ? path.resolve(process.env.PDESURF_TEST_ROOT) : REPO;
const WASM_DIR = process.env.PDESURF_WASM_DIR || path.join(REPO, 'build', 'wasm');
const OUT_DIR = path.join(REPO, 'build', 'browser');
const CHROMIUM = '/usr/bin/chromium';
const BACKGROUND = [0x20, 0x24, 0x2b]; // web/viewer/viewer.js BACKGROUND
const ARGS = [
  '--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync',
  '--use-gl=angle', '--use-angle=swiftshader',
];

const skip = fs.existsSync(CHROMIUM) ? false : `${CHROMIUM} is missing (apt-get install chromium); browser tests skipped`;

describe('modeller page', { skip }, () => {
  let server, context, page, base, userDataDir;
  const problems = []; // console errors, page errors, failed requests

  const hooks = () => page.evaluate(() => {
    const h = window.__pdesurf;
    return { ready: h.ready, solveCount: h.solveCount, lastError: h.lastError, exampleId: h.exampleId,
      checksum: h.checksum(), vertexCount: h.vertexCount() };
  });
  // Wait until a solve after `count` has happened and the frame is painted.
  const solvedAfter = async (count) => {
    await page.waitForFunction((n) => window.__pdesurf.solveCount > n, count, { timeout: 20_000 });
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));
    return hooks();
  };
  const shoot = async (name) => {
    const file = path.join(OUT_DIR, name);
    const png = await page.screenshot({ path: file });
    return decodePng(png);
  };
  // The 3D view minus the panel (right), the title bar (top) and the status line (bottom).
  const viewRect = (img) => ({ x0: 0, y0: 40, x1: img.width - 340, y1: img.height - 50 });

  before(async () => {
    assert.ok(fs.existsSync(path.join(WASM_DIR, 'pdesurf.js')),
      `no wasm module in ${WASM_DIR}: build it first (scripts/build-wasm)`);
    assert.ok(fs.existsSync(path.join(ROOT, 'examples', 'index.json')), `no examples/index.json under ${ROOT}`);
    assert.ok(fs.existsSync(path.join(ROOT, 'node_modules', 'three')), 'node_modules/three is missing: run npm ci');
    fs.mkdirSync(OUT_DIR, { recursive: true });
    server = await startServer({ port: 0, root: ROOT, wasmDir: WASM_DIR });
    base = `http://127.0.0.1:${server.address().port}`;
    userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'pdesurf-chromium-'));
    const { chromium } = await import('playwright-core');
    // A persistent context is how playwright takes --user-data-dir.
    context = await chromium.launchPersistentContext(userDataDir, {
      executablePath: CHROMIUM, args: ARGS, headless: true, viewport: { width: 1280, height: 800 },
    });
    page = await openPage(context.pages()[0]);
  });

  // Fresh page with the problem listeners; a link test loads its URL in a new page
  // rather than navigating, which would abort the old page's fetches.
  async function openPage(existing) {
    if (page && !existing) await page.close();
    const p = existing || (await context.newPage());
    p.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
    p.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
    p.on('requestfailed', (r) => problems.push(`request failed: ${r.url()} ${r.failure()?.errorText}`));
    return p;
  }

  after(async () => {
    await context?.close();
    await new Promise((r) => (server ? server.close(r) : r()));
    if (userDataDir) fs.rmSync(userDataDir, { recursive: true, force: true });
  });

  let drawn; // hooks after the first draw

  it('opens on the first example and draws both surface colours', async () => {
    const index = JSON.parse(fs.readFileSync(path.join(ROOT, 'examples', 'index.json'), 'utf8'));
    await page.goto(`${base}/`);
    await page.waitForFunction(() => window.__pdesurf && (window.__pdesurf.ready || window.__pdesurf.lastError),
      null, { timeout: 30_000 });
    drawn = await hooks();
    assert.equal(drawn.lastError, null, `page reported: ${drawn.lastError}`);
    assert.equal(drawn.ready, true);
    assert.equal(drawn.exampleId, index.examples[0].id);
    assert.ok(drawn.vertexCount > 0 && Number.isFinite(drawn.checksum) && drawn.checksum > 0);
    assert.equal(new URL(page.url()).pathname, '/web/');
    assert.equal(new URL(page.url()).hash, `#example=${encodeURIComponent(index.examples[0].id)}`);

    const img = await shoot('modeller.png');
    const stats = pixelStats(img, viewRect(img), BACKGROUND);
    assert.ok(stats.fraction > 0.03, `canvas looks blank: ${JSON.stringify(stats)}`);
    assert.ok(stats.orange > 200, `no blend-coloured pixels: ${JSON.stringify(stats)}`);
    assert.ok(stats.blue > 200, `no primary-surface-coloured pixels: ${JSON.stringify(stats)}`);
  });

  it('re-solves when a parameter slider is dragged', async () => {
    const slider = page.locator('#panel [data-param] .slider').first();
    const box = await slider.boundingBox();
    assert.ok(box, 'no parameter slider in the panel');
    const before = await hooks();
    // Click two different spots so at least one of them moves the value.
    await page.mouse.click(box.x + box.width * 0.3, box.y + box.height / 2);
    let now = await solvedAfter(before.solveCount);
    if (now.checksum === before.checksum) {
      await page.mouse.click(box.x + box.width * 0.7, box.y + box.height / 2);
      now = await solvedAfter(now.solveCount);
    }
    assert.equal(now.lastError, null);
    assert.notEqual(now.checksum, before.checksum, 'moving a parameter did not change the surfaces');
    drawn = now;
  });

  it('shows a solver error and keeps the last good surfaces', async () => {
    const input = page.locator('#panel [data-operator="x.b"] input').first();
    const original = await input.inputValue();
    const before = await hooks();
    await input.fill('0'); // b = 0 makes the operator degenerate
    const failed = await solvedAfter(before.solveCount);
    assert.ok(failed.lastError, 'b = 0 did not produce an error');
    const status = page.locator('#status');
    assert.ok(await status.isVisible());
    assert.equal(await status.textContent(), failed.lastError);
    assert.match(failed.lastError, /\S/);
    assert.equal(failed.checksum, before.checksum, 'the last good surfaces were replaced');
    assert.equal(failed.vertexCount, before.vertexCount);
    const img = await shoot('modeller-error.png');
    assert.ok(pixelStats(img, viewRect(img), BACKGROUND).fraction > 0.03, 'surfaces vanished on error');

    await input.fill(original); // back to the resolved value: the same surfaces again
    const healed = await solvedAfter(failed.solveCount);
    assert.equal(healed.lastError, null);
    assert.ok(Math.abs(healed.checksum - before.checksum) <= 1e-9 * Math.abs(before.checksum),
      `restoring b gave checksum ${healed.checksum}, expected ${before.checksum}`);
  });

  it('changes a coordinate\'s order and restores its boundary conditions on the way back', async () => {
    page = await openPage();
    await page.goto(`${base}/web/#example=you2004-fig2a`);
    await page.waitForFunction(() => window.__pdesurf.ready, null, { timeout: 30_000 });
    const blend = page.locator('#panel [data-patch="blend"]');
    const order = blend.locator('[data-order="z"] select');
    const before = await hooks();
    assert.equal(before.exampleId, 'you2004-fig2a');
    assert.equal(await order.inputValue(), '4');
    assert.equal(await blend.locator('[data-operator="z.b"]').count(), 1);

    await order.selectOption('2'); // z: order 2, u0/u1 keep only the position condition
    const second = await solvedAfter(before.solveCount);
    assert.equal(second.lastError, null, `order 2 failed: ${second.lastError}`);
    assert.notEqual(second.checksum, before.checksum, 'order 2 did not change the surfaces');
    assert.equal(await blend.locator('[data-operator="z.b"]').count(), 0);
    assert.equal(await blend.locator('[data-operator="z.s"] input').inputValue(), '1');
    assert.equal(await blend.locator('[data-operator="z.t"] input').inputValue(), '1');
    await shoot('modeller-order2.png');

    await order.selectOption('4'); // defaults b = d = 1, c = 2 and the stashed tangent conditions
    const back = await solvedAfter(second.solveCount);
    assert.equal(back.lastError, null);
    assert.equal(back.checksum, before.checksum, 'order 4 again did not give the original surfaces');
    for (const name of ['b', 'c', 'd']) assert.equal(await blend.locator(`[data-operator="z.${name}"]`).count(), 1);
  });

  it('offers the solver\'s methods and shows the one used', async () => {
    const blend = page.locator('#panel [data-patch="blend"]');
    const options = await blend.locator('[data-method="blend"] select option').allTextContents();
    for (const m of ['auto', 'closed']) assert.ok(options.includes(m), `methods offered: ${options}`);
    assert.equal(await blend.locator('[data-method="blend"] select').inputValue(), 'auto');
    assert.equal(await blend.locator('[data-method-used="blend"] input').inputValue(), 'closed');
    await shoot('modeller-methods.png');
  });

  it('re-solves with a chosen method, and "auto" brings back the default', async (t) => {
    const select = page.locator('#panel [data-method="blend"] select');
    const before = await hooks();
    await select.selectOption('closed'); // writes "method": "closed" into the scene
    const chosen = await solvedAfter(before.solveCount);
    if (chosen.lastError) {
      // The page's side is done; the scene reader may not take the field yet.
      assert.match(chosen.lastError, /method/, `choosing "closed" failed: ${chosen.lastError}`);
      t.diagnostic(`solver refused the method field: ${chosen.lastError}`);
    } else {
      // auto picks the closed form here, so the surfaces are the same.
      assert.equal(chosen.checksum, before.checksum);
    }
    await select.selectOption('auto'); // removes the field again
    const auto = await solvedAfter(chosen.solveCount);
    assert.equal(auto.lastError, null);
    assert.equal(auto.checksum, before.checksum);
  });

  it('changes example through the picker and the URL hash', async (t) => {
    const index = JSON.parse(fs.readFileSync(path.join(ROOT, 'examples', 'index.json'), 'utf8'));
    if (index.examples.length < 2) return t.skip('only one example');
    const second = index.examples[1].id;
    const before = await hooks();
    // lil-gui's <option>s carry labels only; pick by position in the catalogue.
    await page.locator('#panel [data-control="example"] select').selectOption({ index: 1 });
    await page.waitForFunction((id) => window.__pdesurf.exampleId === id, second, { timeout: 20_000 });
    const now = await solvedAfter(before.solveCount);
    assert.equal(now.lastError, null);
    assert.equal(new URL(page.url()).hash, `#example=${encodeURIComponent(second)}`);
    await shoot('modeller-second.png');

    // Editing the hash in place (history, hand-edited link) opens that example too.
    const first = index.examples[0].id;
    await page.evaluate((id) => { location.hash = 'example=' + encodeURIComponent(id); }, first);
    await page.waitForFunction((id) => window.__pdesurf.exampleId === id, first, { timeout: 20_000 });
    assert.equal((await solvedAfter(now.solveCount)).lastError, null);

    // A fresh load of the link opens the same example.
    page = await openPage();
    await page.goto(`${base}/web/#example=${encodeURIComponent(second)}`);
    await page.waitForFunction(() => window.__pdesurf.ready, null, { timeout: 30_000 });
    assert.equal((await hooks()).exampleId, second);
  });

  it('shows an unknown example id from a link as text, not markup', async () => {
    const evil = '<img src=x onerror="window.__pwned=1">';
    page = await openPage();
    await page.goto(`${base}/web/#example=${encodeURIComponent(evil)}`);
    await page.waitForFunction(() => window.__pdesurf.ready, null, { timeout: 30_000 });
    const text = await page.locator('#status').textContent();
    assert.ok(text.includes(evil), `status was: ${text}`);
    assert.equal(await page.evaluate(() => document.querySelectorAll('img').length), 0);
    assert.equal(await page.evaluate(() => window.__pwned), undefined);
  });

  it('logged no console error, page error or failed request', () => {
    assert.deepEqual(problems, []);
  });
});
