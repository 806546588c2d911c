// Undo and redo of openings (web/features/history.js): a file and a link are steps and come
// back in the view they were left with; an opening that never draws (a file or a link whose
// scene fails) leaves no step; a Bézier patch's λ, γ, region weights and control-point drag
// are one step each. The changes within a blend: history.test.mjs.
//   node --test tests/browser/history-openings.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { skip, startHarness, shoot, sameChecksum, exampleIndex, ROOT } from './harness.mjs';
import { encodeState } from '../../web/link/link-codec.js';
import { sameCamera, pageTools } from './history-tools.mjs';

describe('undo and redo of openings and of a Bézier patch', { skip }, () => {
  let h;
  before(async () => {
    h = await startHarness();
  });
  after(async () => {
    await h?.close();
  });

  describe('files and links, and openings that never draw', () => {
    let page, t;
    const exampleText = (id) => fs.readFileSync(path.join(ROOT, 'examples', `${id}.json`), 'utf8');
    // you2004-fig2a with an unknown function: it reads, and its solve fails.
    const broken = () => {
      const scene = JSON.parse(exampleText('you2004-fig2a'));
      scene.patches[0].boundary.x.u0[1] = 'r0p*cso(v)';
      return scene;
    };
    const pick = (name, text) => page.locator('[data-file="input"]').setInputFiles({ name, mimeType: 'application/json', buffer: Buffer.from(text) });
    const title = () => page.locator('#scene-title').textContent();
    before(async () => {
      page = await h.open('/web/#example=you2004-fig2a');
      t = pageTools(page);
      await t.typeNumber(t.input('[data-param="r0"]'), 2.2); // an edit, so the scene differs from the example
      await page.waitForFunction(() => window.__pdesurf.history().depth === 1);
    });

    it('opening a file is a step; a file that does not solve leaves no step behind', async () => {
      const edited = await t.settle();
      const h0 = await t.history();
      await pick('hat.json', exampleText('wu2015-fig3'));
      await page.waitForFunction(() => window.__pdesurf.exampleId === null && /hat\.json/.test(document.getElementById('scene-title').textContent));
      const opened = await t.settle();
      assert.equal(opened.lastError, null);
      assert.equal((await t.history()).depth, h0.depth + 1);

      const back = await t.undo();
      assert.equal(back.exampleId, 'you2004-fig2a');
      assert.ok(sameChecksum(back.checksum, edited.checksum));
      assert.equal(await t.input('[data-param="r0"]').inputValue(), '2.2');
      assert.ok(sameCamera(back.camera, edited.camera), 'the cone came back in the hat\'s view');
      await shoot(page, 'history-file-undone.png');
      const again = await t.redo();
      assert.ok(sameChecksum(again.checksum, opened.checksum));
      assert.ok(sameCamera(again.camera, opened.camera));
      assert.match(await title(), /\(hat\.json\)$/);

      // The page shows the hat again after the broken file: the history is as it was.
      const h1 = await t.history();
      await pick('broken.json', JSON.stringify(broken()));
      await page.waitForFunction(() => /^cannot open broken\.json/.test(document.getElementById('status').textContent), null, { timeout: 10_000 });
      const kept = await t.settle();
      assert.ok(sameChecksum(kept.checksum, opened.checksum));
      assert.match(await title(), /\(hat\.json\)$/);
      assert.deepEqual(await t.history(), h1, 'the file that did not solve left a step');
      await shoot(page, 'history-file-refused.png');
      const hat = await t.undo();
      assert.equal(hat.exampleId, 'you2004-fig2a', 'undo after a refused file did not go back past the hat');
    });

    it('a link that does not solve: the default example takes its step', async () => {
      const left = await t.settle();
      const h0 = await t.history();
      const link = await encodeState({ scene: broken(), grid: { nu: 64, nv: 64 } });
      const shown = exampleIndex()[0].id;
      await page.evaluate((l) => { location.hash = l; }, link);
      await page.waitForFunction(() => /cannot open the link/.test(window.__pdesurf.notice ?? ''), null, { timeout: 10_000 });
      const fallback = await t.settle();
      assert.equal(fallback.exampleId, shown);
      assert.deepEqual(await t.history(), { canUndo: true, canRedo: false, depth: h0.depth + 1, redoDepth: 0 });
      await shoot(page, 'history-bad-link.png');
      const back = await t.undo();
      assert.ok(sameChecksum(back.checksum, left.checksum), 'undo went to the broken link, not the scene before it');
      assert.equal(back.lastError, null);
    });

    it('logged no console error, page error or failed request', () => {
      assert.deepEqual(h.problems, []);
    });
  });

  describe('a Bézier patch (wu2015-fig2) and a link', () => {
    let page, t;
    const folder = () => page.locator('#panel [data-bezier="hat"]');
    const cp = (key) => folder().locator(`[data-control-point="hat"] [data-cp="${key}"] input`);
    before(async () => {
      page = await h.open('/web/#example=wu2015-fig2');
      t = pageTools(page);
    });

    it('γ is one step', async () => {
      const gamma = folder().locator('[data-bezier-number="gamma"] input');
      await t.oneStep('γ', { change: () => t.typeNumber(gamma, 20), read: () => gamma.inputValue() });
    });

    it('λ (a parameter of this example) is one step', async () => {
      const lam = t.input('[data-param="lam"]');
      await t.oneStep('λ parameter', { change: () => t.typeNumber(lam, 40), read: () => lam.inputValue() });
    });

    it('a region weight drag is one step; its folder stays open through undo and redo', async () => {
      await folder().locator('[data-region-weights="hat"] > .title').click();
      const weight = folder().locator('[data-region-weight="1.1"]');
      await t.oneStep('region weight', {
        change: () => t.dragSlider(weight.locator('.slider'), 60, 6),
        read: () => weight.locator('input').inputValue(),
        minSolves: 3,
        onUndone: async () => {
          assert.ok(await weight.locator('input').isVisible(), 'the region folder closed on undo');
          await shoot(page, 'history-weights-undone.png');
        },
      });
      assert.ok(await weight.locator('input').isVisible(), 'the region folder closed on redo');
    });

    it('a control-point drag in the view is one step; the edited point and the overlays stay', async () => {
      await folder().locator('[data-control-point="hat"] > .title').click();
      await cp('edit').check();
      await t.frame();
      const at = await page.evaluate(() => window.__pdesurf.controlPointScreen('hat', 5, 2));
      await page.mouse.click(at.x, at.y);
      assert.deepEqual(await page.evaluate(() => window.__pdesurf.editing()), { patch: 'hat', i: 5, j: 2 });
      await folder().locator('[data-bezier-toggle="normals"] input').check();
      const overlays = await page.evaluate(() => window.__pdesurf.overlays());
      assert.equal(overlays.initialNets, 1);
      // The point's z, whichever point the rebuilt editor shows.
      const zOf52 = async () => {
        if (await cp('i').inputValue() !== '5' || await cp('j').inputValue() !== '2') {
          await cp('i').fill('5');
          await cp('j').fill('2');
        }
        return cp('z').inputValue();
      };
      await t.oneStep('control-point drag', {
        change: async () => {
          await page.mouse.move(at.x, at.y - 40);
          await page.mouse.move(at.x, at.y - 45);
          await page.mouse.down();
          for (let k = 1; k <= 6; k++) {
            await page.mouse.move(at.x, at.y - 45 - 10 * k);
            await page.waitForTimeout(40);
          }
          await page.mouse.up();
        },
        read: zOf52,
        minSolves: 3,
        onUndone: async () => {
          // The rebuilt panel keeps the edited point, the pick & drag toggle and the overlays.
          assert.deepEqual(await page.evaluate(() => window.__pdesurf.editing()), { patch: 'hat', i: 5, j: 2 });
          assert.equal(await cp('edit').isChecked(), true);
          assert.deepEqual(await page.evaluate(() => window.__pdesurf.overlays()), overlays);
          await shoot(page, 'history-point-undone.png');
        },
      });
      assert.equal(await cp('edit').isChecked(), true);
      assert.deepEqual(await page.evaluate(() => window.__pdesurf.overlays()), overlays);
      await shoot(page, 'history-point-redone.png');
      await cp('edit').uncheck();
    });

    it('opening a link is a step; its own λ slider is one step; undo goes back to the example', async () => {
      const left = await t.settle();
      const scene = JSON.parse(fs.readFileSync(path.join(ROOT, 'examples', 'wu2015-fig2.json'), 'utf8'));
      scene.patches[0].lambda = 5; // a plain number: the patch's own λ slider
      scene.title = 'Hat with a numeric λ';
      const link = await encodeState({ scene, grid: { nu: 64, nv: 64 } });
      const h0 = await t.history();
      await page.evaluate((l) => { location.hash = l; }, link);
      await page.waitForFunction(() => window.__pdesurf.exampleId === null);
      const opened = await t.settle();
      assert.equal(opened.lastError, null);
      assert.equal((await t.history()).depth, h0.depth + 1);
      assert.match(await page.locator('#scene-title').textContent(), /numeric λ \(shared link\)/);

      const lambda = folder().locator('[data-bezier-number="lambda"] input');
      await t.oneStep('λ slider', { change: () => t.typeNumber(lambda, 30), read: () => lambda.inputValue() });
      await t.undo();
      const back = await t.undo();
      assert.equal(back.exampleId, 'wu2015-fig2');
      assert.ok(sameChecksum(back.checksum, left.checksum));
      assert.ok(sameCamera(back.camera, left.camera));
      assert.match(await page.locator('#scene-title').textContent(), /^Hat with a wavy edge/);
      await shoot(page, 'history-link-undone.png');
    });

    it('logged no console error, page error or failed request', () => {
      assert.deepEqual(h.problems, []);
    });
  });
});
