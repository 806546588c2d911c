// Undo and redo in the page (web/history-wiring.js): every kind of scene change is ONE step
// however many solves it causes (a slider drag or its arrow keys, a typed value, an
// expression, an order, a method, the grid, a control-point drag, λ, γ, region weights,
// adding and removing a parameter, opening an example, a link or a file); undo brings back
// the surface (checksum) and the control's value, redo the change; an opening that never
// draws leaves no step; another scene comes back in the view it was left with; 120 steps undo
// and redo; the keyboard works outside text fields only; the toolbar buttons follow; the hash
// after an undo decodes to the restored state.
// Hooks: window.__pdesurf.history() -> { canUndo, canRedo, depth, redoDepth };
// data-action="undo" | "redo" on the toolbar buttons (web/ui/toolbar.js).
//   node --test tests/browser/history.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { skip, startHarness, hooks, solvedAfter, shoot, sameChecksum, exampleIndex, ROOT, OUT_DIR } from './harness.mjs';
import { decodeFragment, encodeState } from '../../web/link/link-codec.js';
import { REST_MS } from '../../web/history-wiring.js';

const SLOT = 'patches[0].boundary.x.u0[1]'; // you2004-fig2a: "r0p*cos(v)"
const hashOf = (page) => new URL(page.url()).hash;
// Cameras put back through the controls (viewer.setCamera) are equal to rounding.
const sameCamera = (a, b) => [...a.position, ...a.target].every((x, k) => Math.abs(x - [...b.position, ...b.target][k]) < 1e-9);

/** Wait (≤ 3 s) until the hash is a state link whose decoded { scene, grid } satisfies ok(). */
async function linkWhere(page, ok) {
  const t0 = Date.now();
  for (;;) {
    const hash = hashOf(page);
    if (/^#s=1\.[A-Za-z0-9_-]+$/.test(hash)) {
      const state = await decodeFragment(hash);
      if (await ok(state)) return state;
    }
    assert.ok(Date.now() - t0 < 3000, `no matching state link within 3 s; the hash is ${hash.slice(0, 60)}`);
    await page.waitForTimeout(50);
  }
}

/** Helpers over one page. */
function pageTools(page) {
  const t = {
    history: () => page.evaluate(() => window.__pdesurf.history()),
    button: (action) => page.locator(`#toolbar [data-action="${action}"]`),
    input: (selector) => page.locator(`#panel ${selector} input`).first(),
    frame: () => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r()))),

    /** Wait until no solve has come for 300 ms (a drag's trailing solves included). */
    async settle() {
      let last = -1;
      for (let n = (await hooks(page)).solveCount; n !== last; n = (await hooks(page)).solveCount) {
        last = n;
        await page.waitForTimeout(300);
      }
      await t.frame();
      return hooks(page);
    },

    /** Drag a lil-gui slider with the mouse: down, `moves` steps of dx pixels (each re-solves), up. */
    async dragSlider(slider, dx, moves = 8) {
      await slider.scrollIntoViewIfNeeded();
      const box = await slider.boundingBox();
      const y = box.y + box.height / 2;
      const x = box.x + box.width / 2;
      await page.mouse.move(x, y);
      await page.mouse.down();
      for (let k = 1; k <= moves; k++) {
        await page.mouse.move(x + (dx * k) / moves, y);
        await page.waitForTimeout(40); // a frame or two apart: one solve per move
      }
      await page.mouse.up();
    },

    /** Type a number into a panel field and press Enter (lil-gui then leaves the field). */
    async typeNumber(input, value) {
      await input.fill(String(value));
      await input.press('Enter');
    },

    async undo(how = 'button') {
      const n = (await hooks(page)).solveCount;
      if (how === 'button') await t.button('undo').click();
      else await page.keyboard.press(how);
      await solvedAfter(page, n);
      return t.settle();
    },
    async redo(how = 'button') {
      const n = (await hooks(page)).solveCount;
      if (how === 'button') await t.button('redo').click();
      else await page.keyboard.press(how);
      await solvedAfter(page, n);
      return t.settle();
    },

    /**
     * Make one change, check it is exactly one step (and stays one once the changes rest),
     * undo it (surface and control back), redo it (both again). read() -> the control's value.
     * Returns { before, after } (hooks + value).
     */
    async oneStep(label, { change, read, minSolves = 1, surfaceChanges = true, undoHow, redoHow, onUndone }) {
      const h0 = await t.history();
      const before = { ...(await t.settle()), value: await read() };
      await change();
      await page.waitForFunction((d) => window.__pdesurf.history().depth === d + 1, h0.depth, { timeout: 10_000 });
      await t.settle();
      await page.waitForTimeout(REST_MS + 200); // a late second step would show now
      const afterState = { ...(await hooks(page)), value: await read() };
      const h1 = await t.history();
      assert.equal(h1.depth, h0.depth + 1, `${label}: ${h1.depth - h0.depth} steps for one change`);
      assert.equal(h1.canRedo, false, `${label}: a new step keeps a redo branch`);
      assert.ok(afterState.solveCount - before.solveCount >= minSolves,
        `${label}: ${afterState.solveCount - before.solveCount} solves, expected at least ${minSolves}`);
      assert.notEqual(afterState.value, before.value, `${label}: the control did not change`);
      if (surfaceChanges) assert.ok(!sameChecksum(afterState.checksum, before.checksum), `${label}: the surface did not change`);

      const undone = await t.undo(undoHow);
      assert.ok(sameChecksum(undone.checksum, before.checksum), `${label}: undo gave checksum ${undone.checksum}, before ${before.checksum}`);
      assert.equal(await read(), before.value, `${label}: undo did not bring the control's value back`);
      assert.equal(undone.vertexCount, before.vertexCount, `${label}: undo changed the mesh size`);
      assert.deepEqual(await t.history(), { ...h0, canRedo: true, redoDepth: 1 }, `${label}: history after undo`);
      if (onUndone) await onUndone();

      const redone = await t.redo(redoHow);
      assert.ok(sameChecksum(redone.checksum, afterState.checksum), `${label}: redo gave checksum ${redone.checksum}, after ${afterState.checksum}`);
      assert.equal(await read(), afterState.value, `${label}: redo did not bring the change back`);
      assert.deepEqual(await t.history(), h1, `${label}: history after redo`);
      return { before, after: afterState };
    },
  };
  return t;
}

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
