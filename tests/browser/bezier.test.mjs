// Variational Bézier patches in the page (seed 002): drawn in the blend colour, the
// solved and initial control nets and the guiding normals shown on request, the energy
// and normal misfit follow every solve, λ, γ and the region weights re-solve, and a
// point of the initial net can be picked in the view, typed and dragged.
// Hooks: data-bezier="<patch>", data-bezier-toggle, data-bezier-readout,
// data-bezier-number (web/ui/bezier-controls.js), data-region-weight (region-weight-controls.js),
// data-cp (control-point-controls.js); window.__pdesurf.overlays(), editing(),
// controlPointScreen(patch, i, j) (web/main.js).
//   node --test tests/browser/
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { skip, startHarness, hooks, solvedAfter, shoot, viewStats, sameChecksum } from './harness.mjs';

const NORMAL_RGB = [0x5f, 0xe0, 0x8a]; // web/viewer/bezier-overlays.js
const INITIAL_NET_RGB = [0xd7, 0x7c, 0xff];
const SOLVED_NET_RGB = [0xf4, 0xef, 0xd2];

describe('bezier patches', { skip }, () => {
  let h, page;
  const folder = () => page.locator('#panel [data-bezier="hat"]');
  const readout = (key) => folder().locator(`[data-bezier-readout="${key}"] input`).inputValue();
  const overlays = () => page.evaluate(() => window.__pdesurf.overlays());
  const frame = () => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));

  // Pixels of the view within a small distance of one colour (lines are antialiased).
  async function colourCount(img, rgb, tol = 60) {
    const { x0, x1 } = await page.evaluate(() => {
      const v = document.getElementById('viewport').getBoundingClientRect();
      return { x0: Math.ceil(v.left), x1: Math.floor(Math.min(v.right, document.getElementById('panel').getBoundingClientRect().left)) };
    });
    let n = 0;
    for (let y = 40; y < img.height - 50; y++) {
      for (let x = x0; x < x1; x++) {
        const i = (y * img.width + x) * img.channels;
        const d = Math.abs(img.data[i] - rgb[0]) + Math.abs(img.data[i + 1] - rgb[1]) + Math.abs(img.data[i + 2] - rgb[2]);
        if (d <= tol) n++;
      }
    }
    return n;
  }

  // Fill a number field of the panel and wait for the solve it causes.
  async function set(locator, value) {
    const before = await hooks(page);
    await locator.fill(String(value));
    return solvedAfter(page, before.solveCount);
  }

  before(async () => {
    h = await startHarness();
    page = await h.open('/web/');
  });
  after(async () => {
    await h?.close();
  });

  it('opens wu2015-fig2 from the gallery and draws the hat in the blend colour', async () => {
    const before = await hooks(page);
    await page.locator('#gallery [data-example="wu2015-fig2"]').click();
    await page.waitForFunction(() => window.__pdesurf.exampleId === 'wu2015-fig2');
    const drawn = await solvedAfter(page, before.solveCount);
    assert.equal(drawn.lastError, null);
    assert.equal(drawn.vertexCount, 65 * 65);
    const img = await shoot(page, 'bezier-fig2.png');
    const stats = await viewStats(page, img);
    assert.ok(stats.fraction > 0.03, `canvas looks blank: ${JSON.stringify(stats)}`);
    assert.ok(stats.orange > 2000, `the hat is not in the blend colour: ${JSON.stringify(stats)}`);
    assert.deepEqual(await overlays(), { solvedNets: 0, initialNets: 0, netPoints: 0, arrows: 0 });
    assert.equal(await colourCount(img, NORMAL_RGB), 0);
    assert.match(await readout('energy'), /^\d+(\.\d+)?$/);
    // λ is a parameter of the example (slider under Parameters); γ is a plain 0: its own slider.
    assert.equal(await folder().locator('[data-bezier-number="lambda"]').count(), 0);
    assert.equal(await folder().locator('[data-bezier-number="gamma"] input').inputValue(), '0');
  });

  it('shows the initial net, the solved net and the guiding normals on request', async () => {
    const toggle = (key) => folder().locator(`[data-bezier-toggle="${key}"] input`);
    await toggle('initialNet').check();
    await toggle('normals').check();
    await frame();
    assert.deepEqual(await overlays(), { solvedNets: 0, initialNets: 1, netPoints: 64, arrows: 17 * 17 });
    const img = await shoot(page, 'bezier-fig2-net-normals.png');
    const arrows = await colourCount(img, NORMAL_RGB);
    const net = await colourCount(img, INITIAL_NET_RGB);
    assert.ok(arrows > 3000, `arrows barely visible: ${arrows} pixels`);
    assert.ok(net > 500, `initial net barely visible: ${net} pixels`);

    await toggle('initialNet').uncheck();
    await toggle('normals').uncheck();
    await toggle('solvedNet').check();
    await frame();
    assert.deepEqual(await overlays(), { solvedNets: 1, initialNets: 0, netPoints: 64, arrows: 0 });
    const solved = await shoot(page, 'bezier-fig2-solved-net.png');
    assert.ok(await colourCount(solved, SOLVED_NET_RGB, 40) > 500, 'solved net barely visible');
    assert.equal(await colourCount(solved, NORMAL_RGB), 0, 'arrows left on screen');
    await toggle('solvedNet').uncheck();
    await toggle('initialNet').check();
    await toggle('normals').check();
  });

  it('moving λ re-solves: the energy, the misfit and the surface change', async () => {
    const before = await hooks(page);
    const [energy0, misfit0] = [Number(await readout('energy')), Number(await readout('misfit'))];
    const now = await set(page.locator('#panel [data-param="lam"] input'), 40);
    assert.equal(now.lastError, null);
    assert.notEqual(now.checksum, before.checksum);
    const [energy1, misfit1] = [Number(await readout('energy')), Number(await readout('misfit'))];
    assert.notEqual(energy1, energy0);
    assert.ok(misfit1 < misfit0, `a heavier λ must lower the misfit: ${misfit1} against ${misfit0}`);
    assert.deepEqual((await overlays()).arrows, 17 * 17, 'the overlays did not survive the re-solve');
    await shoot(page, 'bezier-fig2-lambda40.png');
  });

  it('a typed interior point of the initial net changes the surface once γ > 0', async () => {
    const cp = (key) => folder().locator(`[data-control-point="hat"] [data-cp="${key}"]`);
    await folder().locator('[data-control-point="hat"] > .title').click();
    await cp('i').locator('input').fill('3');
    await cp('j').locator('input').fill('4');
    assert.equal(await cp('z').locator('input').inputValue(), '0.722394');
    assert.match(await cp('role').locator('input').inputValue(), /no effect while γ = 0/);

    const gamma = await set(folder().locator('[data-bezier-number="gamma"] input'), 20);
    assert.equal(gamma.lastError, null);
    assert.match(await cp('role').locator('input').inputValue(), /pulls the surface through γ/);
    const raised = await set(cp('z').locator('input'), 1.6);
    assert.equal(raised.lastError, null);
    assert.notEqual(raised.checksum, gamma.checksum, 'the edit did not change the surface');
    await shoot(page, 'bezier-fig2-point-raised.png');
    const back = await set(cp('z').locator('input'), 0.722394);
    assert.ok(sameChecksum(back.checksum, gamma.checksum), 'the original value did not give the original surface');
  });

  it('picks a point by clicking it in the view and drags it with the gizmo', async () => {
    const cp = (key) => folder().locator(`[data-control-point="hat"] [data-cp="${key}"]`);
    await cp('edit').locator('input').check();
    await frame();
    assert.deepEqual(await page.evaluate(() => window.__pdesurf.editing()), { patch: 'hat', i: 3, j: 4 });
    // A point in front, away from the gizmo on (3, 4): a press on the gizmo drags, never picks.
    const at = await page.evaluate(() => window.__pdesurf.controlPointScreen('hat', 5, 2));
    await page.mouse.click(at.x, at.y);
    assert.deepEqual(await page.evaluate(() => window.__pdesurf.editing()), { patch: 'hat', i: 5, j: 2 });
    assert.equal(await cp('i').locator('input').inputValue(), '5');
    assert.equal(await cp('j').locator('input').inputValue(), '2');
    const z0 = Number(await cp('z').locator('input').inputValue());

    // The gizmo's z arrow points up the screen from the point: hover it, then drag it up.
    const before = await hooks(page);
    await page.mouse.move(at.x, at.y - 40);
    await page.mouse.move(at.x, at.y - 45);
    await page.mouse.down();
    for (let k = 1; k <= 5; k++) await page.mouse.move(at.x, at.y - 45 - 10 * k);
    await page.mouse.up();
    const dragged = await solvedAfter(page, before.solveCount);
    assert.equal(dragged.lastError, null);
    const z1 = Number(await cp('z').locator('input').inputValue());
    assert.ok(z1 > z0 + 0.05, `z went from ${z0} to ${z1}`);
    assert.match(await cp('z').locator('input').inputValue(), /^-?\d+(\.\d{1,6})?$/, 'a drag writes 6 decimals at most');
    assert.equal(await cp('x').locator('input').inputValue(), '0.428571', 'a z drag moved x');
    assert.equal(await cp('y').locator('input').inputValue(), '-0.428571', 'a z drag moved y');
    assert.notEqual(dragged.checksum, before.checksum);
    assert.deepEqual(dragged.camera, before.camera, 'the camera orbited during the drag');
    await shoot(page, 'bezier-fig2-dragged.png');
    await cp('edit').locator('input').uncheck();
    assert.equal(await page.evaluate(() => window.__pdesurf.editing()), null);
  });

  it('a region weight re-solves, and weight 1 everywhere gives the surface back', async () => {
    await folder().locator('[data-region-weights="hat"] > .title').click();
    const slider = folder().locator('[data-region-weight="1.1"] input');
    const base = await hooks(page);
    const heavy = await set(slider, 10);
    assert.equal(heavy.lastError, null);
    assert.notEqual(heavy.checksum, base.checksum);
    await shoot(page, 'bezier-fig2-weights.png');
    const back = await set(slider, 1);
    assert.ok(sameChecksum(back.checksum, base.checksum));
  });

  it('opens wu2015-fig4 with all five patches and no overlay carried over', async () => {
    const before = await hooks(page);
    await page.locator('#gallery [data-example="wu2015-fig4"]').click();
    await page.waitForFunction(() => window.__pdesurf.exampleId === 'wu2015-fig4');
    const drawn = await solvedAfter(page, before.solveCount);
    assert.equal(drawn.lastError, null);
    assert.equal(drawn.vertexCount, 5 * 65 * 65);
    assert.match(await page.locator('#status').textContent(), /^5 patches/);
    assert.deepEqual(await overlays(), { solvedNets: 0, initialNets: 0, netPoints: 0, arrows: 0 });
    assert.equal(await page.locator('#panel [data-bezier]').count(), 1);
    const fill = page.locator('#panel [data-bezier="fill"]');
    await fill.locator('[data-bezier-toggle="solvedNet"] input').check();
    await fill.locator('[data-bezier-toggle="normals"] input').check();
    await frame();
    assert.deepEqual(await overlays(), { solvedNets: 1, initialNets: 0, netPoints: 64, arrows: 17 * 17 });
    const img = await shoot(page, 'bezier-fig4.png');
    const stats = await viewStats(page, img);
    assert.ok(stats.orange > 1000 && stats.blue > 1000, `both colours: ${JSON.stringify(stats)}`);
    assert.ok(await colourCount(img, NORMAL_RGB) > 1000, 'fig4 arrows barely visible');
  });

  it('logged no console error, page error or failed request', () => {
    assert.deepEqual(h.problems, []);
  });
});
