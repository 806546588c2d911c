// Helpers of the undo and redo tests (history.test.mjs, history-openings.test.mjs): the
// history hook, the toolbar buttons, settling after a gesture's trailing solves, a mouse
// drag of a slider, and oneStep(), which checks that a change is exactly one step that undo
// and redo take back and forth.
import assert from 'node:assert/strict';
import { hooks, solvedAfter, sameChecksum } from './harness.mjs';
import { decodeFragment } from '../../web/link/link-codec.js';
import { REST_MS } from '../../web/features/history.js';

export const hashOf = (page) => new URL(page.url()).hash;
// Cameras put back through the controls (viewer.setCamera) are equal to rounding.
export const sameCamera = (a, b) => [...a.position, ...a.target].every((x, k) => Math.abs(x - [...b.position, ...b.target][k]) < 1e-9);

/** Wait (≤ 3 s) until the hash is a state link whose decoded { scene, grid } satisfies ok(). */
export async function linkWhere(page, ok) {
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
export function pageTools(page) {
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

    /** Undo or redo by its toolbar button or a key (how: 'button' or a key like 'Control+z'). */
    async travel(action, how = 'button') {
      const n = (await hooks(page)).solveCount;
      if (how === 'button') await t.button(action).click();
      else await page.keyboard.press(how);
      await solvedAfter(page, n);
      return t.settle();
    },
    undo: (how) => t.travel('undo', how),
    redo: (how) => t.travel('redo', how),

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
