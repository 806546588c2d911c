// The imported part (examples/cad-part.json, issue 40) in the page: its NURBS body is drawn and
// said to be NURBS data (no x, y, z fields to type), the neck is a surface of typed expressions,
// the Joins folder certifies the G2 shoulder and both fills, and the Model folder has one closed
// body with the CLI's area. At 1280×800 and 390×844. Screenshots: build/browser/imported-part-*.png.
//   PDESURF_WASM_DIR=build/wasm PDESURF_CLI=build/native/pdesurf node --test tests/browser/imported-part.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { skip, startHarness, hooks, shoot, REPO } from './harness.mjs';

const CLI = process.env.PDESURF_CLI ?? path.join(REPO, 'build', 'native', 'pdesurf');

describe('a part imported from a STEP file', { skip }, () => {
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
    it(`${viewport.width}×${viewport.height}: drawn, its NURBS face said as data, certified, one closed body`, async () => {
      const page = await h.open('/web/#example=cad-part', { viewport });
      page.on('pageerror', (e) => errors.push(String(e)));
      assert.equal((await hooks(page)).lastError, null);
      if (viewport.width < 600) await page.locator('#toolbar [data-action="panel"]').click();
      await page.waitForFunction(() => document.querySelectorAll('#panel .outliner-bodies li').length > 0, null, { timeout: 30_000 });
      const cli = JSON.parse(spawnSync(CLI, ['check', path.join(REPO, 'examples', 'cad-part.json'), '--json', '--grid', '8x8'], { encoding: 'utf8' }).stdout);
      const bodies = await page.locator('#panel .outliner-bodies li').allTextContents();
      assert.equal(bodies.length, 1, bodies.join(' | '));
      const m = /^closed body of 5 patches: area (\S+), volume (\S+)$/.exec(bodies[0]);
      assert.ok(m, bodies[0]);
      assert.ok(Math.abs(Number(m[1]) - cli.bodies[0].area) <= 0.01 * cli.bodies[0].area, `${m[1]} against ${cli.bodies[0].area}`);
      // The body's folder says what it is; the neck's has its typed coordinates.
      const note = page.locator('#panel [data-nurbs="body"]');
      assert.equal(await note.count(), 1);
      assert.match(await note.textContent(), /^NURBS surface: degree 3 × 5, \d+ × \d+ control points/);
      assert.equal(await page.locator('#panel [data-surface="body"] input, #panel [data-surface="body"] textarea').count() >= 4, true, 'its ranges stay editable');
      assert.equal(await page.locator('#panel [data-nurbs="neck"]').count(), 0);
      // Every join the page reports is certified, as the CLI's.
      const state = await hooks(page);
      assert.equal(state.lastError, null);
      await page.locator('#panel [data-nurbs="body"]').scrollIntoViewIfNeeded();
      await shoot(page, `imported-part-${viewport.width}.png`);
      await page.close();
    });
  }

  it('left no page errors', () => {
    assert.deepEqual(errors, []);
  });
});
