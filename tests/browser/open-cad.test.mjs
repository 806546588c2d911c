// Opening a CAD file in the page (issue 40, web/features/files.js, web/cad/read-3dm.js): a .3dm
// file — the example part exported as the page does it, made here under node — opens as a
// scene of its faces, each a NURBS surface said as data in the panel and named as before,
// drawn, and its joins' faces ready to blend; a STEP file is refused by name with the command
// that reads it; a bad .3dm keeps what was shown. At 1280×800 and 390×844.
// Screenshots: build/browser/open-cad-*.png.
//   PDESURF_WASM_DIR=build/wasm node --test tests/browser/open-cad.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { skip, startHarness, hooks, shoot, solvedAfter, sameChecksum, ROOT } from './harness.mjs';
import { loadSolver } from '../../web/solver/pdesurf-solver.js';
import { write3dm } from '../../web/cad/write-3dm.js';

const WASM_DIR = process.env.PDESURF_WASM_DIR ? path.resolve(process.env.PDESURF_WASM_DIR) : path.join(ROOT, 'build', 'wasm');

async function partAs3dm() {
  const solver = await loadSolver({ moduleUrl: new URL(`file://${path.join(WASM_DIR, 'pdesurf.js')}`).href, wasmBinary: fs.readFileSync(path.join(WASM_DIR, 'pdesurf.wasm')) });
  const fit = solver.exportCad(fs.readFileSync(path.join(ROOT, 'examples', 'cad-part.json'), 'utf8'), { format: '3dm' });
  return Buffer.from(await write3dm(fit.faces, { tolerance: fit.tolerance, title: fit.title, breps: fit.breps, archive: fit.archive }));
}

describe('opening CAD files', { skip }, () => {
  let h, bytes;
  const errors = [];
  before(async () => {
    h = await startHarness();
    bytes = await partAs3dm();
  });
  after(async () => {
    await h?.close();
  });

  for (const viewport of [{ width: 1280, height: 800 }, { width: 390, height: 844 }]) {
    it(`${viewport.width}×${viewport.height}: a .3dm opens as its faces; STEP and a bad .3dm are refused by name, keeping the scene`, async () => {
      const page = await h.open('/web/#example=you2004-fig2a', { viewport });
      page.on('pageerror', (e) => errors.push(String(e)));
      const pick = (name, buffer) => page.locator('[data-file="input"]').setInputFiles({ name, mimeType: 'application/octet-stream', buffer });
      const refused = async (name, buffer) => {
        await page.evaluate(() => { document.getElementById('status').textContent = ''; });
        await pick(name, buffer);
        await page.waitForFunction(() => /^cannot open /.test(document.getElementById('status').textContent), null, { timeout: 30_000 });
        return page.locator('#status').textContent();
      };
      const before = await hooks(page);
      assert.match(await refused('part.step', Buffer.from('ISO-10303-21;\n')), /^cannot open part\.step: the page does not read STEP files yet: `pdesurf import part\.step -o scene\.json`/);
      assert.match(await refused('junk.3dm', Buffer.alloc(64)), /^cannot open junk\.3dm: ParseError: rhino3dm could not read it as a \.3dm file/);
      const kept = await hooks(page);
      assert.ok(sameChecksum(kept.checksum, before.checksum), 'the drawn surfaces stayed');
      assert.equal(kept.exampleId, 'you2004-fig2a');

      const count = (await hooks(page)).solveCount;
      await pick('part.3dm', bytes);
      const solved = await solvedAfter(page, count);
      assert.equal(solved.lastError, null);
      assert.deepEqual(await page.evaluate(() => window.__pdesurf.lastFile), { action: 'open', name: 'part.3dm', error: null });
      assert.match(await page.locator('#scene-title').textContent(), /part\.3dm/);
      if (viewport.width < 600) await page.locator('#toolbar [data-action="panel"]').click();
      for (const name of ['body', 'neck', 'shoulder', 'base', 'cap']) {
        const note = page.locator(`#panel [data-nurbs="${name}"]`);
        assert.equal(await note.count(), 1, `${name}: a NURBS surface in the panel`);
        assert.match(await note.textContent(), /^NURBS surface: degree 5 × 5, \d+ × \d+ control points/);
      }
      await page.locator('#panel [data-nurbs="body"]').scrollIntoViewIfNeeded();
      await shoot(page, `open-cad-${viewport.width}.png`);
      await page.close();
    });
  }

  it('left no page errors', () => {
    assert.deepEqual(errors, []);
  });
});
