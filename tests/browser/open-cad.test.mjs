// Opening a CAD file in the page (issue 40, web/features/files.js, web/cad/read-3dm.js and
// read-step.js): a .3dm file — the example part exported as the page does it, made here under
// node — opens as a scene of its faces, each a NURBS surface said as data in the panel and named
// as before; the part's STEP file opens through Open CASCADE (its neck a typed cylinder) and
// its two faces are blended G2 in the Build folder (picked in the view at 1280×800, from the
// lists at 390×844), both joins certified; the part exported as
// IGES opens as its B-spline faces, named; a bad IGES, .3dm or STEP keeps what was shown. At
// 1280×800 and 390×844. Screenshots: build/browser/open-cad-*.png, open-iges-*.png, open-step-*.png.
//   PDESURF_WASM_DIR=build/wasm node --test tests/browser/open-cad.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { skip, startHarness, hooks, shoot, solvedAfter, sameChecksum, ROOT } from './harness.mjs';
import { solving, borderPoint } from './build-tools.mjs';
import { loadSolver } from '../../web/solver/pdesurf-solver.js';
import { write3dm } from '../../web/cad/write-3dm.js';
import { OCCT_WASM_BYTES } from '../../web/cad/occt-wasm-size.js';

const APP = process.env.PDESURF_APP_DIR || path.join(ROOT, 'build', 'web');
const built = fs.existsSync(path.join(APP, 'index.html')) && fs.existsSync(path.join(APP, 'occt-worker.js'));
const WASM_DIR = process.env.PDESURF_WASM_DIR ? path.resolve(process.env.PDESURF_WASM_DIR) : path.join(ROOT, 'build', 'wasm');

// The example part as the page exports it: a .3dm (through rhino3dm) and an IGES file.
async function partExports() {
  const solver = await loadSolver({ moduleUrl: new URL(`file://${path.join(WASM_DIR, 'pdesurf.js')}`).href, wasmBinary: fs.readFileSync(path.join(WASM_DIR, 'pdesurf.wasm')) });
  const scene = fs.readFileSync(path.join(ROOT, 'examples', 'cad-part.json'), 'utf8');
  const fit = solver.exportCad(scene, { format: '3dm' });
  const iges = Buffer.from(solver.exportCad(scene, { format: 'iges' }).text, 'latin1');
  return { dm: Buffer.from(await write3dm(fit.faces, { tolerance: fit.tolerance, title: fit.title, breps: fit.breps, archive: fit.archive })), iges };
}

describe('opening CAD files', { skip }, () => {
  let h, bytes, iges;
  const errors = [];
  before(async () => {
    h = await startHarness();
    ({ dm: bytes, iges } = await partExports());
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
      assert.match(await refused('junk.igs', Buffer.from('S      1\n')), /^cannot open junk\.igs: ParseError: not an IGES file/);
      assert.match(await refused('junk.step', Buffer.from('ISO-10303-21;\n')), /^cannot open junk\.step: ParseError: Open CASCADE could not read it as STEP/);
      assert.match(await refused('junk.3dm', Buffer.alloc(64)), /^cannot open junk\.3dm: ParseError: rhino3dm could not read it as a \.3dm file/);
      const kept = await hooks(page);
      assert.ok(sameChecksum(kept.checksum, before.checksum), 'the drawn surfaces stayed');
      assert.equal(kept.exampleId, 'you2004-fig2a');

      const count = (await hooks(page)).solveCount;
      await pick('part.3dm', bytes);
      const solved = await solvedAfter(page, count);
      assert.equal(solved.lastError, null);
      assert.deepEqual(await page.evaluate(() => window.__pdesurf.lastFile), { action: 'open', name: 'part.3dm', error: null, download: null });
      assert.match(await page.locator('#scene-title').textContent(), /part\.3dm/);
      if (viewport.width < 600) await page.locator('#toolbar [data-action="panel"]').click();
      for (const name of ['body', 'neck', 'shoulder', 'base', 'cap']) {
        const note = page.locator(`#panel [data-nurbs="${name}"]`);
        assert.equal(await note.count(), 1, `${name}: a NURBS surface in the panel`);
        assert.match(await note.textContent(), /^NURBS surface: degree 5 × 5, \d+ × \d+ control points/);
      }
      await page.locator('#panel [data-nurbs="body"]').scrollIntoViewIfNeeded();
      await shoot(page, `open-cad-${viewport.width}.png`);

      // The part as an IGES file (the page's own export): its B-spline faces, named as its patches.
      const before3 = (await hooks(page)).solveCount;
      await pick('part.igs', iges);
      assert.equal((await solvedAfter(page, before3)).lastError, null);
      assert.match(await page.locator('#scene-title').textContent(), /part\.igs/);
      for (const name of ['body', 'neck', 'shoulder', 'base', 'cap']) {
        assert.match(await page.locator(`#panel [data-nurbs="${name}"]`).textContent(), /^NURBS surface: degree 5 × 5, \d+ × \d+ control points/, `${name} from IGES`);
      }
      await page.locator('#panel [data-nurbs="body"]').scrollIntoViewIfNeeded();
      await shoot(page, `open-iges-${viewport.width}.png`);

      // The example part's STEP file (examples/cad/part.step) through Open CASCADE in its worker.
      const again = (await hooks(page)).solveCount;
      await pick('part.step', fs.readFileSync(path.join(ROOT, 'examples', 'cad', 'part.step')));
      const opened = await solvedAfter(page, again);
      assert.equal(opened.lastError, null);
      assert.match(await page.locator('#panel [data-nurbs="face 1"]').textContent(), /^NURBS surface: degree 3 × 5, 6 × \d+ control points/);
      assert.equal(await page.locator('#panel [data-surface="face 2"]').count(), 1, 'the neck: a surface of typed expressions');
      assert.equal(await page.locator('#panel [data-nurbs="face 2"]').count(), 0);
      // Blended as a designer would, in the Build folder: the body's top rim into the neck's
      // bottom one, G2 — picked in the view on the wide page, chosen from the lists on the
      // phone; the Joins folder then certifies both joins.
      const control = (key) => page.locator(`#panel [data-build="${key}"] select`);
      await control('blend-continuity').selectOption({ label: 'curvature (G2)' });
      if (viewport.width >= 600) {
        await page.locator('#panel [data-build="blend-pick"] input').check();
        // A point of each rim on the camera's side (the picker names what it hovers).
        const pickRim = async (patch, border) => {
          for (const along of [0.75, 0.25, 0.5, 0]) {
            const p = await borderPoint(page, patch, border, along);
            await page.mouse.move(p.x - 20, p.y - 20);
            await page.mouse.move(p.x, p.y, { steps: 3 });
            const st = await page.evaluate(() => window.__pdesurf.modeller().borders.state());
            if (st.hovered?.patch === patch && st.hovered?.border === border) return page.mouse.click(p.x, p.y);
          }
          assert.fail(`no point of ${patch} ${border} could be picked`);
        };
        await pickRim('face 1', 't1');
        await solving(page, () => pickRim('face 2', 't0'));
      } else {
        await control('blend-a').selectOption({ label: 'face 1 · t1' });
        await control('blend-b').selectOption({ label: 'face 2 · t0' });
        await solving(page, () => page.locator('#panel .build-folder button', { hasText: 'make the blend' }).first().click());
      }
      assert.equal((await hooks(page)).lastError, null);
      await page.waitForFunction(() => document.querySelectorAll('#panel [data-join][data-verdict="ok"]').length === 2, null, { timeout: 30_000 });
      await page.locator('#panel .outliner').scrollIntoViewIfNeeded();
      await shoot(page, `open-step-${viewport.width}.png`);
      await page.close();
    });
  }

  it('the production page opens the STEP file through its own copy of Open CASCADE, saying how much of it has come, and an IGES file', { skip: built ? false : `no ${APP}/occt-worker.js: run node scripts/build-web.mjs` }, async () => {
    const page = await h.open('/app/#example=you2004-fig2a', { viewport: { width: 1280, height: 800 } });
    page.on('pageerror', (e) => errors.push(String(e)));
    // Every text the status line shows while the file opens.
    await page.evaluate(() => {
      const el = document.getElementById('status');
      window.__statusTexts = [];
      new MutationObserver(() => window.__statusTexts.push(el.textContent)).observe(el, { childList: true, characterData: true, subtree: true });
    });
    const count = (await hooks(page)).solveCount;
    await page.locator('[data-file="input"]').setInputFiles({ name: 'part.step', mimeType: 'application/octet-stream', buffer: fs.readFileSync(path.join(ROOT, 'examples', 'cad', 'part.step')) });
    const opened = await solvedAfter(page, count);
    assert.equal(opened.lastError, null);
    assert.equal(await page.locator('#panel [data-nurbs="face 1"]').count(), 1);
    // The first STEP file fetched Open CASCADE's wasm (sent compressed): all of it, counted.
    const { download } = await page.evaluate(() => window.__pdesurf.lastFile);
    assert.deepEqual(download, { loaded: OCCT_WASM_BYTES, total: OCCT_WASM_BYTES });
    const said = await page.evaluate(() => window.__statusTexts);
    const progress = said.filter((t) => /^loading Open CASCADE to read part\.step: [\d.]+ MiB of 21\.9 MiB \(\d+ %\)…$/.test(t));
    assert.ok(progress.length >= 2, `the status line said the download's progress: ${JSON.stringify(said.slice(0, 6))}`);
    assert.ok(said.includes('reading part.step…'), 'then that it reads the file');
    // And an IGES file, through the bundle's own IGES worker.
    const more = (await hooks(page)).solveCount;
    await page.locator('[data-file="input"]').setInputFiles({ name: 'part.igs', mimeType: 'application/octet-stream', buffer: iges });
    assert.equal((await solvedAfter(page, more)).lastError, null);
    assert.equal(await page.locator('#panel [data-nurbs="body"]').count(), 1);
    await page.close();
  });

  it('left no page errors', () => {
    assert.deepEqual(errors, []);
  });
});
