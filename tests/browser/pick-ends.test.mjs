// Picking a pde patch's end in the view, for fills and blends alike (issue 35): a vase (a pde
// patch with typed ends) capped by a PDE fill of its top end, picked, and filleted into a
// ring below by a blend from its bottom end, picked; both certified G1 in the page and by
// the CLI from the link. At 1280×800 and 390×844.
// Screenshots: build/browser/pick-ends-*.png.
//   PDESURF_WASM_DIR=build/wasm PDESURF_CLI=build/native/pdesurf node --test tests/browser/pick-ends.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { skip, startHarness, hooks, shoot } from './harness.mjs';
import { CLI, clickBorder, solving, checkLink } from './build-tools.mjs';
import { encodeState } from '../../web/link/link-codec.js';

const scene = (page) => page.evaluate(() => JSON.parse(window.__pdesurf.sceneText()));
const control = (page, key) => page.locator(`#panel [data-build="${key}"]`);
const button = (page, name) => page.locator('#panel .build-folder button', { hasText: name }).first();

function vase() {
  return {
    format: 'pdesurf-scene', version: 4, title: 'vase',
    patches: [
      { name: 'vase', kind: 'pde', v_range: [0, '2*pi'], operator: { order: 4, b: 1, c: 2, d: 1 },
        boundary: { x: { u0: ['cos(v)', '0'], u1: ['0.6*cos(v)', '0'] }, y: { u0: ['sin(v)', '0'], u1: ['0.6*sin(v)', '0'] }, z: { u0: ['0', '2'], u1: ['2', '2'] } } },
      { name: 'ring', kind: 'surface', t_range: [0, 1], v_range: [0, '2*pi'], x: '(1.6 + t)*cos(v)', y: '(1.6 + t)*sin(v)', z: '-0.6' },
    ],
  };
}

describe('picking pde ends for fills and blends', { skip }, () => {
  let h;
  const errors = [];
  before(async () => {
    assert.ok(fs.existsSync(CLI), `no CLI at ${CLI}`);
    h = await startHarness();
  });
  after(async () => {
    await h?.close();
  });

  for (const viewport of [{ width: 1280, height: 800 }, { width: 390, height: 844 }]) {
    it(`${viewport.width}×${viewport.height}: a PDE fill of the vase's top end and a blend from its bottom end, both picked`, async () => {
      const page = await h.open(`/web/#${await encodeState({ scene: vase() })}`, { viewport });
      page.on('pageerror', (e) => errors.push(String(e)));
      page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
      assert.equal((await hooks(page)).lastError, null);
      // On a phone the panel covers the view: it is opened to choose and closed to pick.
      const phone = viewport.width < 600;
      const togglePanel = async () => phone && page.locator('#toolbar [data-action="panel"]').click();
      await togglePanel();
      // The choices offer the vase's ends beside the ring's borders.
      const offered = await control(page, 'blend-a').locator('option').allTextContents();
      for (const label of ['vase · u0', 'vase · u1', 'ring · t0', 'ring · t1']) assert.ok(offered.includes(label), `${label} in ${offered}`);

      await page.locator('#panel .build-folder .title', { hasText: 'Fill a loop' }).click(); // closed at first
      await control(page, 'fill-kind').locator('select').selectOption({ label: 'PDE (1–8 borders)' });
      await control(page, 'fill-pick').locator('input').check();
      await togglePanel();
      await clickBorder(page, 'vase', 'u1', 0.25);
      await shoot(page, `pick-ends-hover-${viewport.width}.png`);
      await solving(page, async () => {
        await togglePanel();
        await button(page, 'fill the loop').click();
      });
      assert.equal((await hooks(page)).lastError, null);
      let s = await scene(page);
      assert.deepEqual(s.patches[2], { name: 'fill1', kind: 'fill', borders: [{ patch: 'vase', at: 'u1' }] });

      await control(page, 'fill-pick').locator('input').uncheck();
      await control(page, 'blend-pick').locator('input').check();
      await togglePanel();
      await clickBorder(page, 'vase', 'u0', 0.25);
      await solving(page, () => clickBorder(page, 'ring', 't0', 0.25));
      assert.equal((await hooks(page)).lastError, null);
      s = await scene(page);
      const blend = s.patches.find((p) => p.name === 'blend1');
      assert.deepEqual(blend.ends.u0, { patch: 'vase', at: 'u0', continuity: 'tangency', power: 1 });
      assert.deepEqual(blend.ends.u1, { surface: 'ring', at: 't0', continuity: 'tangency', power: 1 });
      // Certified in the page: the fill's join with the vase, the blend's two, all G1.
      await page.waitForFunction(() => (window.__pdesurf.analysis().report?.joins ?? []).some((j) => j.patch === 'blend1'), null, { timeout: 20_000 });
      const joins = await page.evaluate(() => window.__pdesurf.analysis().report.joins);
      const mine = joins.filter((j) => j.patch === 'fill1' || j.patch === 'blend1');
      assert.equal(mine.length, 3, JSON.stringify(joins));
      assert.ok(mine.every((j) => j.ok && j.level === 'G1'), JSON.stringify(mine));
      await shoot(page, `pick-ends-${viewport.width}.png`);
      await page.waitForFunction(() => location.hash.startsWith('#s='), null, { timeout: 10_000 });
      await page.waitForTimeout(400);
      const { report } = checkLink(await page.evaluate(() => location.href));
      assert.equal(report.ok, true);
      await page.close();
    });
  }

  it('left no console or page errors', () => {
    assert.deepEqual(errors, []);
  });
});
