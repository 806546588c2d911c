// The camera cannot be lost: the fit button and F frame every patch, zoom stops at limits
// set by the scene's size with the clipping planes following (the surface never vanishes
// or gets cut), double-click on a surface makes that point the orbit centre, the focused
// canvas orbits with the arrow keys and zooms with + and −, and the camera stays in the
// share link. web/viewer/camera-rig.js.
//   node --test tests/browser/camera.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { skip, startHarness, hooks, shoot, viewStats } from './harness.mjs';
import { decodeFragment } from '../../web/link/link-codec.js';

const dist = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
const rig = (page) => page.evaluate(() => window.__pdesurf.cameraState());
const frame = (page) => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));

describe('camera', { skip }, () => {
  let h, page, fitted;
  before(async () => {
    h = await startHarness();
    page = await h.open('/web/#example=you2004-fig4a');
    fitted = (await hooks(page)).camera;
  });
  after(async () => {
    await h?.close();
  });

  async function wheel(times, deltaY) {
    const box = await page.locator('#viewport canvas').boundingBox();
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    for (let k = 0; k < times; k++) await page.mouse.wheel(0, deltaY);
    await frame(page);
  }

  it('zooming in stops at 1 % of the scene radius and the surface stays drawn, unclipped', async () => {
    await wheel(80, -400);
    const s = await rig(page);
    assert.ok(s.radius > 0);
    assert.ok(s.distance >= 0.01 * s.radius * (1 - 1e-9), `distance ${s.distance}, radius ${s.radius}`);
    assert.ok(s.distance <= 0.02 * s.radius, `the zoom stopped early at ${s.distance / s.radius} radii`);
    assert.ok(s.near <= 0.02 * s.distance * (1 + 1e-9), `near ${s.near} for an orbit distance ${s.distance}`);
    const img = await shoot(page, 'camera-zoomed-in.png');
    assert.ok((await viewStats(page, img)).fraction > 0.5, 'the view is not filled by the surface');
  });

  it('zooming out stops at 20 radii, with the far plane behind the whole scene', async () => {
    await wheel(120, 400);
    const s = await rig(page);
    assert.ok(Math.abs(s.distance / s.radius - 20) < 1e-6, `distance ${s.distance / s.radius} radii`);
    const cam = (await hooks(page)).camera;
    const toCentre = dist(cam.position, s.centre);
    assert.ok(s.far >= toCentre + s.radius, `far ${s.far} < ${toCentre + s.radius}`);
    assert.ok(s.near <= toCentre - s.radius, `near ${s.near} cuts the scene`);
    const img = await shoot(page, 'camera-zoomed-out.png');
    const st = await viewStats(page, img);
    assert.ok(st.fraction > 0.002 && st.fraction < 0.05, `surface covers ${st.fraction}`);
  });

  it('the fit button and the F key frame every patch again', async () => {
    await page.locator('[data-action="fit"]').click();
    await frame(page);
    let cam = (await hooks(page)).camera;
    assert.ok(dist(cam.position, fitted.position) < 1e-9 * (1 + dist(fitted.position, fitted.target)), JSON.stringify(cam));
    assert.ok(dist(cam.target, fitted.target) < 1e-9);
    await wheel(10, 400);
    await page.locator('body').press('f');
    await frame(page);
    cam = (await hooks(page)).camera;
    assert.ok(dist(cam.position, fitted.position) < 1e-9 * (1 + dist(fitted.position, fitted.target)));
    // Not while typing: an f in a text field is text.
    await wheel(5, 400);
    const before = (await hooks(page)).camera;
    const field = page.locator('#panel [data-param-new="name"] input');
    await field.focus();
    await page.keyboard.press('f');
    assert.equal(await field.inputValue(), 'f');
    assert.deepEqual((await hooks(page)).camera, before);
    await field.fill('');
    await page.locator('[data-action="fit"]').click();
    await shoot(page, 'camera-fit.png');
  });

  it('double-click on a surface makes that point the orbit centre, in the middle of the view', async () => {
    const k = 40 * 64 + 20; // a vertex of the blend, off the middle of the view
    const p = await page.evaluate((i) => window.__pdesurf.vertexScreen('blend', i), k);
    const before = (await hooks(page)).camera;
    await page.mouse.dblclick(p.x, p.y);
    await frame(page);
    const after = (await hooks(page)).camera;
    assert.ok(dist(after.target, before.target) > 1e-3, 'the target did not move');
    // The view direction is kept: the camera slid with the target.
    const d0 = before.position.map((x, i) => x - before.target[i]);
    const d1 = after.position.map((x, i) => x - after.target[i]);
    assert.ok(dist(d0, d1) < 1e-9 * Math.hypot(...d0));
    // The new centre is the clicked point: it now projects to the middle of the canvas.
    const mid = await page.evaluate((t) => {
      const c = document.querySelector('#viewport canvas').getBoundingClientRect();
      const s = window.__pdesurf.screenOf(t);
      return { dx: s.x - (c.left + c.width / 2), dy: s.y - (c.top + c.height / 2), clicked: null };
    }, after.target);
    assert.ok(Math.hypot(mid.dx, mid.dy) < 0.5, JSON.stringify(mid));
    // And it lies on the surface near the vertex clicked.
    const vertexWorld = await page.evaluate((i) => window.__pdesurf.vertexWorld('blend', i), k);
    const s = await rig(page);
    assert.ok(dist(vertexWorld, after.target) < 0.05 * s.radius, `${dist(vertexWorld, after.target)} from the vertex`);
    await shoot(page, 'camera-dblclick.png');
    // A double-click on the background changes nothing.
    const box = await page.locator('#viewport canvas').boundingBox();
    await page.mouse.dblclick(box.x + 8, box.y + box.height - 60);
    assert.deepEqual((await hooks(page)).camera, after);
  });

  it('the focused canvas orbits with the arrow keys and zooms with + and −', async () => {
    await page.locator('[data-action="fit"]').click();
    const canvas = page.locator('#viewport canvas');
    await canvas.focus();
    assert.equal(await page.evaluate(() => document.activeElement.tagName), 'CANVAS');
    const c0 = (await hooks(page)).camera;
    const az = (c) => Math.atan2(c.position[1] - c.target[1], c.position[0] - c.target[0]);
    await page.keyboard.press('ArrowLeft');
    const c1 = (await hooks(page)).camera;
    let turn = (az(c1) - az(c0)) * 180 / Math.PI;
    turn = ((turn + 540) % 360) - 180;
    assert.ok(Math.abs(Math.abs(turn) - 7.5) < 1e-6, `turned ${turn}°`);
    assert.ok(Math.abs(dist(c1.position, c1.target) - dist(c0.position, c0.target)) < 1e-9);
    await page.keyboard.press('ArrowUp');
    const c2 = (await hooks(page)).camera;
    assert.ok(Math.abs(c2.position[2] - c1.position[2]) > 1e-6, 'up did not change the elevation');
    const d2 = dist(c2.position, c2.target);
    await page.keyboard.press('+');
    const d3 = dist((await hooks(page)).camera.position, (await hooks(page)).camera.target);
    assert.ok(Math.abs(d3 - d2 / 1.15) < 1e-9 * d2, `zoomed in to ${d3 / d2}`);
    await page.keyboard.press('-');
    const d4 = dist((await hooks(page)).camera.position, (await hooks(page)).camera.target);
    assert.ok(Math.abs(d4 - d2) < 1e-9 * d2);
    await shoot(page, 'camera-keys.png');
  });

  it('the camera stays in the share link and a reload shows the same view', async () => {
    const cam = (await hooks(page)).camera;
    // An edit makes the hash a state link; a camera move then updates it once the view rests.
    const slider = page.locator('#panel [data-param] .slider').first();
    await slider.focus();
    const n = (await hooks(page)).solveCount;
    await page.keyboard.press('ArrowRight');
    await page.waitForFunction((c) => window.__pdesurf.solveCount > c, n);
    await page.locator('#viewport canvas').focus();
    await page.keyboard.press('ArrowRight');
    const moved = (await hooks(page)).camera;
    assert.notDeepEqual(moved, cam);
    await page.waitForFunction(() => location.hash.startsWith('#s='), null, { timeout: 10_000 });
    await page.waitForTimeout(900); // the link follows a resting camera after 500 ms
    const link = await page.evaluate(() => location.hash.slice(1));
    const state = await decodeFragment(link);
    assert.ok(dist(state.camera.position, moved.position) < 1e-9 && dist(state.camera.target, moved.target) < 1e-9);
    const again = await h.open(`/web/#${link}`);
    const got = (await hooks(again)).camera;
    assert.ok(dist(got.position, moved.position) < 1e-9 && dist(got.target, moved.target) < 1e-9, JSON.stringify(got));
    await again.close();
  });

  it('logged no console error, page error or failed request', () => {
    assert.deepEqual(h.problems, []);
  });
});
