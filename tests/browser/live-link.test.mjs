// The address bar follows the page state: an opened example keeps "#example=<id>";
// a slider move or an orbit rewrites it as "#s=1.…" (replaceState, no
// history entries) and that URL reproduces the page; a failed solve leaves the last
// good state; the page's own writes never re-open the state, while a hash typed in does.
//   node --test tests/browser/
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { skip, startHarness, hooks, solvedAfter, shoot, sameChecksum } from './harness.mjs';
import { decodeFragment } from '../../web/link/link-codec.js';

const EXAMPLE = 'you2004-fig2a';
const hashOf = (page) => new URL(page.url()).hash;
const r0 = (page) => page.locator('#panel [data-param="r0"] input');
// Sliders snap to their step, so a typed 2.3 may be stored as 2.2998.
const about = (v, want) => Math.abs(v - want) < 0.005;
const near = (a, b) => a.every((x, i) => Math.abs(x - b[i]) <= 1e-6 * Math.max(1, Math.abs(b[i])));

/** Wait (≤ 2 s) until the hash is a state link that decodes and satisfies `ok`. */
async function linkWhere(page, ok = () => true) {
  const t0 = Date.now();
  for (;;) {
    const hash = hashOf(page);
    if (/^#s=1\.[A-Za-z0-9_-]+$/.test(hash)) {
      const state = await decodeFragment(hash);
      if (ok(state)) return { hash, state, ms: Date.now() - t0 };
    }
    assert.ok(Date.now() - t0 < 2000, `no matching #s=1.… link within 2 s; hash is ${hash.slice(0, 60)}`);
    await page.waitForTimeout(50);
  }
}

// The hooks once the page has stopped solving (no new solve for 400 ms, at most 10 s): a
// slider drag solves some of the values it passes, and the surface its link must reproduce
// is the last one drawn, not the first after the drag began.
async function settled(page) {
  let count = -1;
  for (let waited = 0; waited < 10_000; waited += 400) {
    const now = await page.evaluate(() => window.__pdesurf.solveCount);
    if (now === count) break;
    count = now;
    await page.waitForTimeout(400);
  }
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));
  return hooks(page);
}

/** Drag the r0 slider by dx pixels with the mouse, as a user does. */
async function dragSlider(page, dx) {
  const box = await page.locator('#panel [data-param="r0"] .slider').boundingBox();
  const y = box.y + box.height / 2;
  await page.mouse.move(box.x + box.width / 2, y);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + dx, y, { steps: 8 });
  await page.mouse.up();
}

describe('the address bar follows the page state', { skip }, () => {
  let h;
  before(async () => {
    h = await startHarness();
  });
  after(async () => {
    await h?.close();
  });

  it('a freshly opened example keeps its #example= link', async () => {
    const page = await h.open(`/web/#example=${EXAMPLE}`);
    // A click on the view that moves nothing is no change either.
    const canvas = await page.locator('#viewport canvas').boundingBox();
    await page.mouse.click(canvas.x + canvas.width / 3, canvas.y + canvas.height / 3);
    await page.waitForTimeout(1200); // past the camera debounce
    assert.equal(hashOf(page), `#example=${EXAMPLE}`);
    assert.equal(await page.locator('#panel [data-share="length"] input').inputValue(), `${page.url().length} characters`);
    await page.close();
  });

  it('a slider move rewrites the hash, and that URL reproduces the page', async () => {
    const page = await h.open(`/web/#example=${EXAMPLE}`);
    const historyLength = await page.evaluate(() => history.length);
    const before = await hooks(page);
    const start = await r0(page).inputValue();
    await dragSlider(page, 40);
    const now = await solvedAfter(page, before.solveCount);
    assert.equal(now.lastError, null);
    const value = await r0(page).inputValue();
    assert.notEqual(value, start, 'the slider did not move');
    const { hash, state, ms } = await linkWhere(page, (s) => about(s.scene.parameters.r0.value, Number(value)));
    const drawn = await settled(page);
    assert.ok(near(state.camera.position, now.camera.position), 'the link lost the camera');
    assert.equal(await page.evaluate(() => history.length), historyLength, 'the hash writes added history entries');
    assert.equal(await page.locator('#panel [data-share="length"] input').inputValue(), `${page.url().length} characters`);
    await shoot(page, 'live-link-source.png');
    console.log(`# hash followed the slider in ${ms} ms, ${page.url().length} characters`);

    const opened = await h.open(`/web/${hash}`);
    const got = await hooks(opened);
    assert.equal(got.lastError, null, got.lastError);
    assert.equal(got.exampleId, null);
    assert.ok(sameChecksum(got.checksum, drawn.checksum), `checksum ${got.checksum}, expected ${drawn.checksum}`);
    assert.equal(await r0(opened).inputValue(), value);
    assert.equal(hashOf(opened), hash, 'opening a link must not rewrite it');
    await shoot(opened, 'live-link-opened.png');
    await opened.close();
    await page.close();
  });

  it('quick edits: the last state wins; an orbit alone updates the camera', async () => {
    const page = await h.open(`/web/#example=${EXAMPLE}`);
    for (const v of ['1.7', '1.9', '2.05', '2.3']) await r0(page).fill(v);
    await linkWhere(page, (s) => about(s.scene.parameters.r0.value, 2.3));
    await page.waitForTimeout(300); // nothing older may land afterwards
    assert.ok(about((await decodeFragment(hashOf(page))).scene.parameters.r0.value, 2.3), 'an older state landed last');

    const before = hashOf(page);
    const canvas = await page.locator('#viewport canvas').boundingBox();
    await page.mouse.move(canvas.x + canvas.width / 2, canvas.y + canvas.height / 2);
    await page.mouse.down();
    await page.mouse.move(canvas.x + canvas.width / 2 - 150, canvas.y + canvas.height / 2 + 30, { steps: 6 });
    await page.mouse.up();
    const camera = (await hooks(page)).camera;
    const { state } = await linkWhere(page, (s) => near(s.camera.position, camera.position));
    assert.notEqual(hashOf(page), before);
    assert.ok(about(state.scene.parameters.r0.value, 2.3));
    await page.close();
  });

  it('the page never re-opens its own hash; a hash typed in still opens', async () => {
    const page = await h.open(`/web/#example=${EXAMPLE}`);
    await r0(page).fill('2.4');
    await linkWhere(page, (s) => about(s.scene.parameters.r0.value, 2.4));
    const before = await hooks(page);
    const title = await page.locator('#scene-title').textContent();
    // What a hashchange for the page's own write would do: nothing.
    await page.evaluate(() => window.dispatchEvent(new HashChangeEvent('hashchange')));
    await page.waitForTimeout(500);
    const after = await hooks(page);
    assert.equal(after.solveCount, before.solveCount, 'the page re-opened its own link');
    assert.equal(await page.locator('#scene-title').textContent(), title);

    // The same example typed in again opens it afresh, with its own value (1.8).
    await page.evaluate((id) => { location.hash = `example=${id}`; }, EXAMPLE);
    await solvedAfter(page, after.solveCount);
    await page.waitForFunction(() => document.querySelector('#panel [data-param="r0"] input')?.value === '1.8',
      null, { timeout: 10_000 });
    assert.equal(hashOf(page), `#example=${EXAMPLE}`);
    await page.close();
  });

  it('a solve that fails leaves the last good state in the hash, orbits included', async () => {
    const page = await h.open(`/web/#example=${EXAMPLE}`);
    await r0(page).fill('2.4');
    const { hash } = await linkWhere(page, (s) => about(s.scene.parameters.r0.value, 2.4));
    const before = await hooks(page);
    await page.locator('#panel [data-expr="patches[0].boundary.x.u0[1]"] input').fill('r0p*cso(v)');
    assert.match((await solvedAfter(page, before.solveCount)).lastError, /cso/);
    await page.waitForTimeout(600);
    assert.equal(hashOf(page), hash, 'a failed solve changed the link');
    const canvas = await page.locator('#viewport canvas').boundingBox();
    await page.mouse.move(canvas.x + canvas.width / 2, canvas.y + canvas.height / 2);
    await page.mouse.down();
    await page.mouse.move(canvas.x + canvas.width / 2 + 100, canvas.y + canvas.height / 2, { steps: 5 });
    await page.mouse.up();
    const camera = (await hooks(page)).camera;
    const { state } = await linkWhere(page, (s) => near(s.camera.position, camera.position));
    assert.equal(state.scene.patches[0].boundary.x.u0[1], 'r0p*cos(v)', 'the broken scene went into the link');
    assert.match(await page.locator('#status').getAttribute('class'), /error/, 'the error left the status line');
    await page.close();
  });

  it('logged no console error, page error or failed request', () => {
    assert.deepEqual(h.problems, []);
  });
});
