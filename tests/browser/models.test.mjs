// Models of many patches in the page (docs/chains-and-fills.md): the aeroplane (you2004-fig8d)
// draws with every join and every fill's centre certified in the Joins folder, the outliner
// shows what each patch is derived from, a wing's parameter re-solves only the patches
// downstream of the wing; and a PDE fill made from borders chosen in the Build folder closes
// four strips G1. At 1280×800 and 390×844 (one page, resized).
// Screenshots: build/browser/models-*.png.
//   PDESURF_WASM_DIR=build/wasm node --test tests/browser/models.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { skip, startHarness, hooks, solvedAfter, shoot } from './harness.mjs';
import { encodeState } from '../../web/link/link-codec.js';

async function openFolder(page, name) {
  if (!(await page.locator('#panel').isVisible())) await page.locator('#toolbar [data-action="panel"]').click();
  const folder = page.locator(`#panel [data-folder="${name}"]`);
  if (await folder.evaluate((el) => el.classList.contains('closed'))) await folder.locator(':scope > .title').click();
  return folder;
}

const report = (page) => page.evaluate(() => window.__pdesurf.analysis().report);

describe('models of many patches', { skip }, () => {
  let h;
  before(async () => {
    h = await startHarness();
  });
  after(async () => {
    await h?.close();
  });

  it('the aeroplane: joins and centres certified in the Joins folder, the chain in the outliner, a wing re-solves only its blends', async () => {
    const page = await h.open('/web/#example=you2004-fig8d');
    assert.equal((await hooks(page)).lastError, null);
    const joins = await openFolder(page, 'joins');
    await page.waitForFunction(() => window.__pdesurf.analysis().report?.centres?.length > 0);
    const r = await report(page);
    assert.equal(r.joins.length, 27);
    assert.ok(r.joins.every((j) => j.ok), JSON.stringify(r.joins.filter((j) => !j.ok)));
    assert.equal(r.centres.length, 10);
    assert.ok(r.centres.every((c) => c.ok));
    assert.equal(await joins.locator('[data-join][data-verdict="ok"]').count(), 27);
    assert.equal(await joins.locator('[data-centre][data-verdict="ok"]').count(), 10);
    assert.match(await joins.locator('[data-centre="mid_top"]').textContent(), /^“mid_top” centre: normal spread .*: regular$/);
    // The outliner: what each patch is derived from.
    assert.equal(await page.locator('#panel [data-patch="front2"] .outliner-deps').textContent(), '← front1');
    assert.equal(await page.locator('#panel [data-patch="rootL"] .outliner-deps').textContent(), '← wingL');
    assert.match(await page.locator('#panel [data-patch="mid_top"] .outliner-deps').textContent(), /^← front2, rootL, rear1, rootR$/);
    await shoot(page, 'models-plane-1280.png');
    // One wing parameter: only what the wings reach is solved again.
    // (Opening Joins re-solved with the crossing test: let that land first.)
    await page.waitForFunction(() => window.__pdesurf.analysis().report?.crossingsChecked === true);
    const n = (await hooks(page)).solveCount;
    const field = page.locator('#panel [data-param="wing_x"] input');
    await field.fill('0.1');
    await field.press('Enter');
    await page.waitForFunction(() => JSON.parse(window.__pdesurf.sceneText()).parameters.wing_x.value === 0.1);
    const after = await solvedAfter(page, n);
    assert.equal(after.lastError, null);
    const resolved = await page.evaluate(() => window.__pdesurf.lastSolve.resolved);
    assert.deepEqual([...resolved].sort(), ['rootL', 'rootR', 'tipL', 'tipR']);
    await page.setViewportSize({ width: 390, height: 844 });
    await openFolder(page, 'joins');
    await shoot(page, 'models-plane-390.png');
    await page.close();
  });

  it('a PDE fill of four strips made from the Build folder meets every strip G2, its seam too', async () => {
    const strip = (k) => ({ name: `strip${k}`, kind: 'surface', t_range: [1, 2], v_range: [-1, 1],
      x: 't', y: 'v', z: 'c*(t^2 + v^2)', ...(k ? { placement: { rotate: [0, 0, 90 * k] } } : {}) });
    const scene = { format: 'pdesurf-scene', version: 4, title: 'four strips',
      parameters: { c: { value: 0.1, min: 0, max: 0.3 } }, patches: [0, 1, 2, 3].map(strip) };
    const page = await h.open(`/web/#${await encodeState({ scene })}`);
    assert.equal((await hooks(page)).lastError, null);
    await page.locator('#panel .build-folder .title', { hasText: 'Fill a loop' }).click();
    const control = (key) => page.locator(`#panel [data-build="${key}"]`);
    await control('fill-kind').locator('select').selectOption({ label: 'PDE (1–8 borders)' });
    assert.equal(await page.locator('#panel [data-build^="fill-"] select').count(), 10, 'the kind, the continuity and eight border choices');
    await control('fill-continuity').locator('select').selectOption({ label: 'curvature (G2)' });
    for (const k of [0, 2, 1, 3]) await control(`fill-${[0, 2, 1, 3].indexOf(k)}`).locator('select').selectOption({ label: `strip${k} · t0` });
    const n = (await hooks(page)).solveCount;
    await page.locator('#panel .build-folder button', { hasText: 'fill the loop' }).click();
    const after = await solvedAfter(page, n);
    assert.equal(after.lastError, null);
    const built = JSON.parse(await page.evaluate(() => window.__pdesurf.sceneText()));
    const fill = built.patches.find((p) => p.kind === 'fill');
    assert.equal(fill.borders.length, 4);
    assert.equal(fill.continuity, 'curvature');
    await openFolder(page, 'joins');
    await page.waitForFunction(() => window.__pdesurf.analysis().report?.centres?.length === 1);
    const r = await report(page);
    assert.equal(r.joins.filter((j) => j.patch === fill.name).length, 4);
    assert.ok(r.joins.every((j) => j.ok && j.level === 'G2'), JSON.stringify(r.joins));
    assert.ok(r.centres[0].ok);
    // The fill closes on itself: its seam is certified G2 and listed in the Joins folder.
    const seam = r.seams.find((j) => j.patch === fill.name);
    assert.ok(seam && seam.ok && seam.level === 'G2', JSON.stringify(r.seams));
    assert.equal(await page.locator(`#panel .joins-seam[data-seam="${fill.name}"]`).getAttribute('data-verdict'), 'ok');
    await shoot(page, 'models-fill-1280.png');
    await page.close();
  });
});
