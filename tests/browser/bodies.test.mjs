// The Model folder shows the model's bodies from the solve's report (issue 36): the bottle
// example one closed body with its area and volume (the CLI's `pdesurf check` figures), fig4a
// one open body with its two free edges. At 1280×800 and 390×844.
// Screenshots: build/browser/bodies-*.png.
//   PDESURF_WASM_DIR=build/wasm PDESURF_CLI=build/native/pdesurf node --test tests/browser/bodies.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { skip, startHarness, hooks, shoot, REPO } from './harness.mjs';

const CLI = process.env.PDESURF_CLI ?? path.join(REPO, 'build', 'native', 'pdesurf');

// `pdesurf check`'s bodies, the reference for the page's.
function cliBodies(id) {
  const r = spawnSync(CLI, ['check', path.join(REPO, 'examples', `${id}.json`), '--json', '--grid', '8x8'], { encoding: 'utf8' });
  return JSON.parse(r.stdout).bodies;
}

const bodyLines = (page) => page.locator('#panel .outliner-bodies li').allTextContents();

describe('bodies in the Model folder', { skip }, () => {
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
    it(`${viewport.width}×${viewport.height}: the bottle is one closed body with the CLI's area and volume; fig4a one open body`, async () => {
      const page = await h.open('/web/#example=bottle-solid', { viewport });
      page.on('pageerror', (e) => errors.push(String(e)));
      assert.equal((await hooks(page)).lastError, null);
      if (viewport.width < 600) await page.locator('#toolbar [data-action="panel"]').click();
      await page.waitForFunction(() => document.querySelectorAll('#panel .outliner-bodies li').length > 0, null, { timeout: 20_000 });
      const [cli] = cliBodies('bottle-solid');
      const lines = await bodyLines(page);
      assert.equal(lines.length, 1, lines.join(' | '));
      const m = /^closed body of 5 patches: area (\S+), volume (\S+)$/.exec(lines[0]);
      assert.ok(m, lines[0]);
      assert.ok(Math.abs(Number(m[1]) - cli.area) <= 0.01 * cli.area, `${m[1]} against ${cli.area}`);
      assert.ok(Math.abs(Number(m[2]) - cli.volume) <= 0.01 * cli.volume, `${m[2]} against ${cli.volume}`);
      await page.locator('#panel .outliner').scrollIntoViewIfNeeded();
      await shoot(page, `bodies-${viewport.width}.png`);
      await page.close();

      const open = await h.open('/web/#example=you2004-fig4a', { viewport });
      if (viewport.width < 600) await open.locator('#toolbar [data-action="panel"]').click();
      await open.waitForFunction(() => document.querySelectorAll('#panel .outliner-bodies li').length > 0, null, { timeout: 20_000 });
      assert.deepEqual(await bodyLines(open), [`open body of 3 patches (2 free edges): area ${Number(cliBodies('you2004-fig4a')[0].area.toPrecision(4))}`]);
      await open.close();
    });
  }

  it('left no page errors', () => {
    assert.deepEqual(errors, []);
  });
});
