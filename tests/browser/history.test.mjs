// Undo and redo in the page (web/features/history.js): every kind of scene change is ONE step
// however many solves it causes (a slider drag or its arrow keys, a typed value, an
// expression, an order, a method, the grid, a control-point drag, λ, γ, region weights,
// adding and removing a parameter, opening an example); undo brings back the surface
// (checksum) and the control's value, redo the change; 120 steps undo and redo; the keyboard
// works outside text fields only; the toolbar buttons follow; the hash after an undo decodes
// to the restored state. Files, links, openings that never draw and a Bézier patch:
// history-openings.test.mjs; the shared helpers: history-tools.mjs.
// Hooks: window.__pdesurf.history() -> { canUndo, canRedo, depth, redoDepth };
// data-action="undo" | "redo" on the toolbar buttons (web/ui/toolbar.js).
//   node --test tests/browser/history.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { skip, startHarness, hooks, shoot, sameChecksum, OUT_DIR } from './harness.mjs';
import { REST_MS } from '../../web/features/history.js';
import { sameCamera, linkWhere, pageTools } from './history-tools.mjs';

const SLOT = 'patches[0].boundary.x.u0[1]'; // you2004-fig2a: "r0p*cos(v)"

describe('undo and redo', { skip }, () => {
  let h;
  before(async () => {
    h = await startHarness();
  });
  after(async () => {
    await h?.close();
  });

  describe('a blend (you2004-fig2a)', () => {
    let page, t;
    const param = (name) => page.locator(`#panel [data-param="${name}"]`);
    const expr = (p) => page.locator(`#panel [data-expr="${p}"] input`);
    before(async () => {
      page = await h.open('/web/#example=you2004-fig2a');
      t = pageTools(page);
    });

    it('starts at the base: nothing to undo or redo, both buttons disabled', async () => {
      assert.deepEqual(await t.history(), { canUndo: false, canRedo: false, depth: 0, redoDepth: 0 });
      assert.equal(await t.button('undo').isDisabled(), true);
      assert.equal(await t.button('redo').isDisabled(), true);
      assert.match(await t.button('undo').getAttribute('title'), /Undo \((Ctrl|⌘)/);
      await shoot(page, 'history-base.png');
      await page.locator('#toolbar').screenshot({ path: path.join(OUT_DIR, 'history-toolbar-base.png') });
      // Ctrl+Z at the base does nothing (and no solve).
      const n = (await hooks(page)).solveCount;
      await page.keyboard.press('Control+z');
      await page.waitForTimeout(300);
      assert.equal((await hooks(page)).solveCount, n);
    });

    it('a slider drag of many solves is one step; the buttons follow', async () => {
      const read = () => t.input('[data-param="r0"]').inputValue();
      await t.oneStep('slider drag', {
        change: () => t.dragSlider(param('r0').locator('.slider'), 60, 10),
        read,
        minSolves: 4, // the drag really re-solved several times
        onUndone: async () => {
          assert.equal(await t.button('undo').isDisabled(), true);
          assert.equal(await t.button('redo').isDisabled(), false);
          await shoot(page, 'history-drag-undone.png');
          await page.locator('#toolbar').screenshot({ path: path.join(OUT_DIR, 'history-toolbar-redo-only.png') });
        },
      });
      assert.equal(await t.button('undo').isDisabled(), false);
      assert.equal(await t.button('redo').isDisabled(), true);
      await shoot(page, 'history-drag-redone.png');
    });

    it('two drags in a row are two steps', async () => {
      const h0 = await t.history();
      await t.dragSlider(param('r1').locator('.slider'), 30, 4);
      await t.dragSlider(param('r1').locator('.slider'), -60, 4);
      await t.settle();
      await page.waitForTimeout(REST_MS + 200);
      assert.equal((await t.history()).depth, h0.depth + 2);
    });

    it('arrow keys on a focused slider are one step once they rest', async () => {
      const slider = param('h1p').locator('.slider');
      await t.oneStep('slider keys', {
        change: async () => {
          await slider.focus();
          for (let k = 0; k < 3; k++) await page.keyboard.press('ArrowRight');
        },
        read: () => t.input('[data-param="h1p"]').inputValue(),
      });
    });

    it('an operator coefficient drag is one step; the blend folder shows the old number after undo', async () => {
      await t.oneStep('operator slider', {
        change: () => t.dragSlider(page.locator('#panel [data-operator="x.b"] .slider'), 50, 6),
        read: () => t.input('[data-operator="x.b"]').inputValue(),
        minSolves: 3,
      });
    });

    it('a number typed key by key with pauses is one step, taken at Enter', async () => {
      const input = t.input('[data-param="r0"]');
      await t.oneStep('typed value', {
        change: async () => {
          await input.fill('');
          await input.pressSequentially('2.45', { delay: REST_MS + 100 }); // each key re-solves, then rests
          assert.equal((await t.history()).canRedo, false);
          await input.press('Enter');
        },
        read: () => input.inputValue(),
        minSolves: 2,
      });
    });

    it('an expression is one step when its field is left (Enter); Ctrl+Z in the field stays the field\'s own', async () => {
      const field = expr(SLOT);
      const h0 = await t.history();
      // Typing and undoing inside the field: the page's history is untouched.
      await field.click();
      await page.keyboard.press('End');
      await page.keyboard.type('*2', { delay: 30 });
      await page.keyboard.press('Control+z');
      await page.waitForTimeout(REST_MS + 200);
      assert.equal(await field.inputValue(), 'r0p*cos(v)', 'the field\'s own undo did not run');
      assert.deepEqual(await t.history(), h0, 'Ctrl+Z in a text field reached the page\'s history');
      await field.press('Enter');

      await t.oneStep('expression', {
        change: async () => {
          await field.fill('r0p*cos(v)*1.5');
          await t.settle();
          await page.waitForTimeout(REST_MS + 100);
          assert.equal((await t.history()).depth, h0.depth, 'committed while the field still had the focus');
          await field.press('Enter');
        },
        read: () => field.inputValue(),
      });
    });

    it('an order change is one step; undo gives the old order and its function fields back', async () => {
      const slots = () => page.locator('#panel [data-functions="blend"] [data-axis="x"] [data-expr]').count();
      assert.equal(await slots(), 5); // u0, u1 × 2 conditions, and the force
      await t.oneStep('order', {
        change: () => page.locator('#panel [data-order="x"] select').selectOption('6'),
        read: () => page.locator('#panel [data-order="x"] select').inputValue(),
        onUndone: async () => assert.equal(await slots(), 5),
      });
      assert.equal(await slots(), 7);
      await t.undo();
      assert.equal(await slots(), 5);
      assert.equal((await t.history()).canRedo, true);
    });

    it('a method change is one step', async () => {
      const select = page.locator('#panel [data-method="blend"] select');
      const methods = await select.locator('option').evaluateAll((os) => os.map((o) => o.value));
      const other = methods.find((m) => m.startsWith('modal:'));
      assert.ok(other, `no modal method among ${methods}`);
      const used = () => t.input('[data-method-used="blend"]').inputValue();
      const { before, after: changed } = await t.oneStep('method', {
        change: () => select.selectOption(other),
        read: async () => `${await select.inputValue()} / ${await used()}`,
        surfaceChanges: false, // this blend's boundary functions are single modes: every method draws the same surface
      });
      assert.equal(before.value, 'auto / closed');
      assert.equal(changed.value, `${other} / ${other}`);
    });

    it('a change after an undo cuts the redo branch', async () => {
      await t.undo();
      assert.equal((await t.history()).canRedo, true);
      await t.typeNumber(t.input('[data-param="h1"]'), 2.5);
      await page.waitForFunction(() => !window.__pdesurf.history().canRedo, null, { timeout: 5000 });
      assert.equal(await t.button('redo').isDisabled(), true);
    });

    it('a grid change is one step; undo gives the old mesh size', async () => {
      await page.locator('#panel .lil-gui:has([data-grid="nu"]) > .title').click();
      const nu = t.input('[data-grid="nu"]');
      const { before, after: changed } = await t.oneStep('grid', {
        change: () => t.typeNumber(nu, 48),
        read: () => nu.inputValue(),
      });
      assert.equal(before.value, '64');
      assert.equal(changed.vertexCount * 65, before.vertexCount * 49); // (nu + 1) rows of vertices
    });

    it('removing a parameter (×) is one step: undo brings it back and heals the error', async () => {
      const { before, after: removed } = await t.oneStep('remove parameter', {
        change: () => page.locator('#panel [data-param-remove="r0p"]').click(),
        read: async () => `${await param('r0p').count()} ${await page.locator('#panel .expr-error:visible').count()}`,
        surfaceChanges: false, // the solve fails: the last good surfaces stay
        onUndone: async () => {
          assert.equal((await hooks(page)).lastError, null);
          await shoot(page, 'history-remove-undone.png');
        },
      });
      assert.equal(before.value, '1 0');
      assert.equal(removed.value, '0 1');
      assert.match(removed.lastError, /unknown parameter 'r0p'/);
      await shoot(page, 'history-remove-redone.png');
      const healed = await t.undo();
      assert.equal(healed.lastError, null);
      assert.equal(await t.input('[data-param="r0p"]').inputValue(), '-0.5');
    });

    it('adding a parameter is one step', async () => {
      await t.input('[data-param-new="name"]').fill('k');
      await t.input('[data-param-new="value"]').fill('0.3');
      await t.oneStep('add parameter', {
        change: () => page.locator('#panel [data-param-add] button').click(),
        read: async () => String(await param('k').count()),
        surfaceChanges: false, // nothing uses it yet
      });
      assert.equal(await t.input('[data-param="k"]').inputValue(), '0.3');
    });

    it('the keyboard: Ctrl+Z, Ctrl+Shift+Z, Ctrl+Y and Cmd+Z from the body and the canvas', async () => {
      const input = t.input('[data-param="r0"]');
      await page.evaluate(() => document.activeElement?.blur());
      await t.oneStep('Ctrl+Z / Ctrl+Shift+Z', {
        change: () => t.typeNumber(input, 1.2),
        read: () => input.inputValue(),
        undoHow: 'Control+z',
        redoHow: 'Control+Shift+Z',
      });
      // With the focus on the view (a click that moves nothing).
      const canvas = await page.locator('#viewport canvas').boundingBox();
      await t.oneStep('Cmd+Z / Ctrl+Y', {
        change: async () => {
          await t.typeNumber(input, 1.4);
          await page.mouse.click(canvas.x + canvas.width / 3, canvas.y + canvas.height / 3);
        },
        read: () => input.inputValue(),
        undoHow: 'Meta+z',
        redoHow: 'Control+y',
      });
      // In a number field of the panel, Ctrl+Z is the field's.
      const h0 = await t.history();
      await input.click();
      await page.keyboard.press('Control+z');
      await page.waitForTimeout(REST_MS);
      assert.deepEqual(await t.history(), h0);
      await input.press('Enter');
    });

    it('the hash after an undo decodes to the restored state', async () => {
      const input = t.input('[data-param="r1"]');
      const r1 = async () => Number(await input.inputValue());
      await t.typeNumber(input, 0.9);
      await t.settle();
      const saved = await linkWhere(page, async (s) => s.scene.parameters.r1.value === await r1());

      await t.typeNumber(input, 1.3);
      await t.settle();
      const changed = await linkWhere(page, async (s) => s.scene.parameters.r1.value === await r1());
      assert.notDeepEqual(changed.scene, saved.scene);

      await t.undo('Control+z');
      const restored = await linkWhere(page, (s) => s.scene.parameters.r1.value === saved.scene.parameters.r1.value);
      assert.deepEqual(restored.scene, saved.scene, 'the hash after undo is not the restored scene');
      assert.deepEqual(restored.grid, saved.grid);
      assert.deepEqual(restored.grid, { nu: 48, nv: 64 }, 'the grid step above is in the link');
    });

    it('opening an example is a step: undo gives the previous scene back with its edits and its view', async () => {
      // An orbit first: the view changes, the history does not.
      const depth = (await t.history()).depth;
      const canvas = await page.locator('#viewport canvas').boundingBox();
      await page.mouse.move(canvas.x + canvas.width / 2, canvas.y + canvas.height / 2);
      await page.mouse.down();
      await page.mouse.move(canvas.x + canvas.width / 2 - 120, canvas.y + canvas.height / 2 + 40, { steps: 6 });
      await page.mouse.up();
      await page.waitForTimeout(REST_MS + 200);
      assert.equal((await t.history()).depth, depth, 'an orbit made a step');
      const left = await t.settle();
      const title = await page.locator('#scene-title').textContent();
      const h0 = await t.history();
      await page.locator('#gallery [data-example="you2004-fig2b"]').click();
      await page.waitForFunction(() => window.__pdesurf.exampleId === 'you2004-fig2b');
      const opened = await t.settle();
      assert.deepEqual(await t.history(), { canUndo: true, canRedo: false, depth: h0.depth + 1, redoDepth: 0 });

      const back = await t.undo();
      assert.equal(back.exampleId, 'you2004-fig2a');
      assert.ok(sameChecksum(back.checksum, left.checksum), 'the previous scene came back without its edits');
      assert.ok(sameCamera(back.camera, left.camera), 'the scene did not come back framed as it was left');
      assert.ok(!sameCamera(opened.camera, left.camera), 'the example opened in the same view: the test shows nothing');
      assert.equal(await page.locator('#scene-title').textContent(), title);
      assert.equal(await page.locator('#gallery .gallery-item.active').getAttribute('data-example'), 'you2004-fig2a');
      assert.equal(await t.input('[data-param="k"]').inputValue(), '0.3', 'the added parameter was lost');
      await shoot(page, 'history-example-undone.png');

      const again = await t.redo();
      assert.equal(again.exampleId, 'you2004-fig2b');
      assert.ok(sameChecksum(again.checksum, opened.checksum));
      assert.ok(sameCamera(again.camera, opened.camera), 'redo did not give the example its view back');
      assert.equal(await page.locator('#gallery .gallery-item.active').getAttribute('data-example'), 'you2004-fig2b');
      await t.undo();
    });

    it('120 changes, then 110 undos and 110 redos all land', async () => {
      const input = t.input('[data-param="r0"]');
      const h0 = await t.history();
      // 120 typed values, as typeNumber makes them (input, then the focus leaves) but in the
      // page: through playwright this test took minutes.
      const states = await page.evaluate(async (n) => {
        const field = document.querySelector('#panel [data-param="r0"] input');
        const out = [];
        for (let k = 1; k <= n; k++) {
          field.focus();
          field.value = (1 + 0.01 * k).toFixed(2);
          field.dispatchEvent(new Event('input', { bubbles: true }));
          field.blur();
          await new Promise((r) => setTimeout(r, 0)); // the commit runs once the focus has left
          await new Promise((r) => setTimeout(r, 0));
          out.push(field.value);
        }
        return out;
      }, 120);
      assert.equal(new Set(states).size, 120);
      const top = await t.settle();
      const full = await t.history();
      assert.equal(full.depth, Math.min(h0.depth + 120, 200));

      // The shortcut's own keydown events, sent in the page: a real key press waits for the
      // frame and the solve it causes (about half a second each here, with software WebGL).
      const keys = (n, init) => page.evaluate(({ n, init }) => {
        document.activeElement?.blur();
        for (let k = 0; k < n; k++) window.dispatchEvent(new KeyboardEvent('keydown', { ...init, bubbles: true, cancelable: true }));
      }, { n, init });
      await keys(110, { key: 'z', ctrlKey: true });
      const low = await t.settle();
      assert.equal((await t.history()).depth, full.depth - 110);
      assert.equal((await t.history()).redoDepth, 110);
      assert.equal(await input.inputValue(), states[120 - 110 - 1]);
      await shoot(page, 'history-110-undone.png');
      await page.locator('#toolbar').screenshot({ path: path.join(OUT_DIR, 'history-toolbar-both.png') });

      await keys(110, { key: 'Z', ctrlKey: true, shiftKey: true });
      const high = await t.settle();
      assert.ok(sameChecksum(high.checksum, top.checksum));
      assert.ok(!sameChecksum(low.checksum, top.checksum));
      assert.equal(await input.inputValue(), states[119]);
      assert.deepEqual(await t.history(), full);
    });

    it('logged no console error, page error or failed request', () => {
      assert.deepEqual(h.problems, []);
    });
  });
});
