// The File folder's CAD exports in the production page (/app/: build/web or $PDESURF_APP_DIR;
// web/features/files.js, web/export/cad-export.js, the solver worker's exportCad): nothing of
// them (nor of rhino3dm) is fetched at load; STEP and IGES of you2004-fig4a read back in Open
// CASCADE within the fit's tolerance of the native CLI's own samples (occt_readback), the
// .3dm reads back in rhino3dm under node (one valid Brep of the 3 faces, pointAt within the tolerance of
// the same samples); the line under the buttons gives the achieved figures; a bad tolerance
// or an unreachable one is a message (text, never markup), nothing is downloaded, and the page
// keeps working; an edit during an export waits for it. Screenshots of the folder after an
// export at 1280×800 and 390×844 with a touch pointer (build/browser/cad-export-*.png).
//   PDESURF_WASM_DIR=build/wasm PDESURF_CLI=build/native/pdesurf \
//   PDESURF_OCCT_READBACK=build/native/tests/occt/occt_readback node --test tests/browser/cad-export.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { skip, startHarness, recordRequestsAndCsp, coldStart, shoot, solvedAfter, OUT_DIR, ROOT, REPO } from './harness.mjs';
import { loadRhino3dm } from '../../web/cad/load-rhino3dm.js';

const APP = process.env.PDESURF_APP_DIR || path.join(REPO, 'build', 'web');
const built = fs.existsSync(path.join(APP, 'index.html')) && fs.existsSync(path.join(APP, 'rhino-worker.js'));
const CLI = process.env.PDESURF_CLI || path.join(ROOT, 'build', 'native', 'pdesurf');
const READBACK = process.env.PDESURF_OCCT_READBACK || path.join(path.dirname(CLI), 'tests', 'occt', 'occt_readback');
const ID = 'you2004-fig4a';
const EXAMPLE = path.join(ROOT, 'examples', `${ID}.json`);
const CAD_DIR = path.join(OUT_DIR, 'cad');
const NAMES = ['blend', 'cylinder', 'plane'];
const why = !built ? `no ${APP}/index.html with rhino-worker.js: run node scripts/build-web.mjs`
  : !fs.existsSync(CLI) ? `no CLI at ${CLI} (set PDESURF_CLI)`
    : !fs.existsSync(READBACK) ? `no occt_readback at ${READBACK} (set PDESURF_OCCT_READBACK)` : false;

/** The CLI's surface of every patch of the example: [{ name, samples: [[u, v, x, y, z], ...] }]. */
function cliSamples(names) {
  return names.map((name) => {
    const r = spawnSync(CLI, ['sample', EXAMPLE, '--patch', name, '--grid', '9x13'], { encoding: 'utf8' });
    assert.equal(r.status, 0, r.stderr);
    return { name, samples: r.stdout.trim().split('\n').slice(1).map((l) => l.split(',').map(Number)) };
  });
}

const folderSel = '#panel [data-folder="file"]';
const button = (key) => `${folderSel} [data-file="${key}"] button`;
const toleranceInput = `${folderSel} [data-file="cad-tolerance"] input`;
const cadLine = `${folderSel} [data-file="cad-message"]`;

async function openFolder(page) {
  await page.locator(`${folderSel} > .title`).click();
  await page.waitForFunction((s) => !document.querySelector(s).matches('.closed, .transition'), folderSel);
}

/** Click an export button and catch its download: { name, bytes, ms (click to file), lastFile }. */
async function download(page, key) {
  await page.evaluate(() => { window.__pdesurf.lastFile = null; });
  const t0 = Date.now();
  const [d] = await Promise.all([
    page.waitForEvent('download', { timeout: 120_000 }),
    page.locator(button(key)).click(),
  ]);
  const bytes = fs.readFileSync(await d.path());
  const ms = Date.now() - t0;
  await page.waitForFunction(() => window.__pdesurf.lastFile !== null);
  return { name: d.suggestedFilename(), bytes, ms, lastFile: await page.evaluate(() => window.__pdesurf.lastFile) };
}

/** Click an export that must fail: { lastFile, line, lineClass, status, downloads } (downloads meanwhile). */
async function refused(page, key, counter) {
  const before = counter.n;
  await page.evaluate(() => { window.__pdesurf.lastFile = null; });
  await page.locator(button(key)).click();
  await page.waitForFunction(() => window.__pdesurf.lastFile !== null, null, { timeout: 120_000 });
  await page.waitForTimeout(300); // a download would have started by now
  return page.evaluate(([sel, n]) => {
    const el = document.querySelector(sel);
    return { lastFile: window.__pdesurf.lastFile, line: el.textContent, lineClass: el.className, lineHtml: el.innerHTML,
      status: document.getElementById('status').textContent, statusClass: document.getElementById('status').className, downloads: n };
  }, [cadLine, counter.n - before]);
}

function readBack(file, tolerance, names) {
  const expect = `${file}.expect.json`;
  fs.writeFileSync(expect, JSON.stringify({ tolerance, faces: cliSamples(names) }));
  const r = spawnSync(READBACK, [file, expect], { encoding: 'utf8' });
  assert.equal(r.status, 0, `${path.basename(file)}: ${r.stdout.slice(0, 800)} ${r.stderr.slice(0, 400)}`);
}

describe('CAD exports from the page (/app/)', { skip: skip || why }, () => {
  let h, page;
  let requests = [];
  const downloads = { n: 0 };
  const figures = [];
  let loadRequests = [];
  let fit = null; // hooks.lastFile of the first STEP export

  before(async () => {
    fs.mkdirSync(CAD_DIR, { recursive: true });
    h = await startHarness();
    requests = await recordRequestsAndCsp(h);
  });
  after(async () => {
    if (figures.length) console.log(`# cad exports: ${figures.join('; ')}`);
    await h?.close();
  });

  it('a cold start fetches nothing of the CAD export and stays within the budget', async () => {
    const cold = await coldStart(h, `${h.base}/app/#example=${ID}`);
    assert.ok(cold.bytes < 1 << 20, `${cold.bytes} bytes on the wire`);
    figures.push(`cold start ${cold.ms.toFixed(0)} ms, ${(cold.bytes / 1024).toFixed(0)} KiB`);
    requests.length = 0;
    page = await h.open(`/app/#example=${ID}`);
    page.on('download', () => { downloads.n++; });
    assert.equal(await page.evaluate(() => window.__pdesurf.lastError), null);
    loadRequests = [...requests];
    assert.deepEqual(loadRequests.filter((p) => /rhino/i.test(p)), [], 'rhino3dm fetched at load');
    await openFolder(page);
    for (const key of ['cad-tolerance', 'step', 'iges', '3dm']) assert.ok(await page.locator(`${folderSel} [data-file="${key}"]`).isVisible(), key);
    assert.equal(await page.locator(cadLine).isVisible(), false, 'the CAD line shows before any export');
    for (const label of ['STEP', 'IGES', '3dm']) assert.ok(await page.getByRole('button', { name: `export ${label}`, exact: true }).isVisible(), label);
  });

  it('STEP: the first export loads its chunk, fits in the worker and reads back in Open CASCADE', async () => {
    const mark = requests.length;
    const step = await download(page, 'step');
    assert.equal(step.name, `${ID}.step`);
    const text = step.bytes.toString('latin1');
    assert.match(text, /^ISO-10303-21;/);
    for (const name of NAMES) assert.ok(text.includes(`ADVANCED_FACE('${name}'`), name);
    const lazy = requests.slice(mark).filter((p) => p.endsWith('.js'));
    assert.ok(lazy.length >= 1 && lazy.every((p) => !loadRequests.includes(p)), `scripts on the first click: ${lazy}`);
    assert.deepEqual(requests.filter((p) => /rhino/i.test(p)), [], 'rhino3dm fetched for STEP');
    fit = step.lastFile;
    assert.equal(fit.action, 'step');
    assert.equal(fit.bytes, step.bytes.length);
    assert.deepEqual(fit.faces.map((f) => f.name), NAMES);
    assert.ok(fit.tolerance > 0);
    // fig. 4a's two G1 joins, measured between the written faces.
    assert.deepEqual(fit.joins.map((j) => [j.patch, j.end, j.level, j.ok]), [['blend', 'u0', 'G1', true], ['blend', 'u1', 'G1', true]]);
    for (const j of fit.joins) assert.ok(j.gap <= j.allowedGap && j.normalDeg <= 0.01, JSON.stringify(j));
    for (const f of fit.faces) assert.ok(f.deviation <= fit.tolerance, `${f.name}: ${f.deviation} > ${fit.tolerance}`);
    const worst = Math.max(...fit.faces.map((f) => f.deviation));
    const line = await page.locator(cadLine).textContent();
    const m = /^STEP: 3 faces, certified within (\S+) \(tolerance (\S+)\)$/.exec(line);
    assert.ok(m, line);
    assert.deepEqual([Number(m[1]), Number(m[2])], [worst, fit.tolerance].map((x) => Number(x.toPrecision(2))), line);
    assert.match(await page.locator('#status').textContent(), new RegExp(`^saved ${ID}\\.step \\(\\d+ KiB\\)$`));
    const file = path.join(CAD_DIR, step.name);
    fs.writeFileSync(file, step.bytes);
    readBack(file, fit.tolerance, NAMES);
    figures.push(`first STEP ${fit.ms.toFixed(0)} ms in the page (fit + write ${fit.fitMs.toFixed(0)} ms in the worker; ${step.ms} ms click to file), ${step.bytes.length} bytes`);
    await page.locator(folderSel).scrollIntoViewIfNeeded();
    await shoot(page, 'cad-export-desktop.png');
  });

  it('IGES reads back in Open CASCADE', async () => {
    const iges = await download(page, 'iges');
    assert.equal(iges.name, `${ID}.igs`);
    assert.equal(iges.lastFile.tolerance, fit.tolerance);
    const lines = iges.bytes.toString('latin1').split(/\r?\n/).filter(Boolean);
    assert.ok(lines.every((l) => l.length === 80), 'IGES records are 80 columns');
    assert.match(await page.locator(cadLine).textContent(), /^IGES: 3 faces, certified within /);
    const file = path.join(CAD_DIR, iges.name);
    fs.writeFileSync(file, iges.bytes);
    readBack(file, fit.tolerance, NAMES);
    figures.push(`IGES ${iges.lastFile.ms.toFixed(0)} ms, ${iges.bytes.length} bytes`);
  });

  it('3dm: rhino3dm loads on the first click only, and reads the file back in node', async () => {
    assert.deepEqual(requests.filter((p) => /rhino/i.test(p)), [], 'rhino3dm fetched before the 3dm click');
    const first = await download(page, '3dm');
    assert.equal(first.name, `${ID}.3dm`);
    assert.ok(requests.includes('/app/rhino3dm/rhino3dm.wasm'), `requests: ${requests.filter((p) => /rhino/i.test(p))}`);
    assert.match(await page.locator(cadLine).textContent(), /^3dm: 3 faces, certified within /);
    fs.writeFileSync(path.join(CAD_DIR, first.name), first.bytes);
    const rh = await loadRhino3dm();
    const file = rh.File3dm.fromByteArray(new Uint8Array(first.bytes));
    try {
      assert.equal(file.settings().modelAbsoluteTolerance, fit.tolerance);
      // One body: the three faces joined in one Brep (open: the cylinder's and the plane's far borders).
      const objects = file.objects();
      assert.equal(objects.count, 1);
      const o = objects.get(0);
      assert.equal(o.attributes().getUserString('pdesurf.faces'), NAMES.join(', '));
      const brep = o.geometry();
      assert.ok(brep.isValid, brep.isValidWithLog[1]);
      assert.equal(brep.isSolid, false);
      const faces = brep.faces();
      assert.equal(faces.count, 3);
      const expected = cliSamples(NAMES);
      for (let k = 0; k < faces.count; k++) {
        const srf = faces.get(k);
        let worst = 0;
        for (const [u, v, x, y, z] of expected[k].samples) {
          const p = srf.pointAt(u, v);
          worst = Math.max(worst, Math.hypot(p[0] - x, p[1] - y, p[2] - z));
        }
        assert.ok(worst <= fit.tolerance, `${NAMES[k]}: ${worst} > ${fit.tolerance}`);
        srf.delete();
      }
      brep.delete();
    } finally {
      file.delete();
    }
    const again = await download(page, '3dm');
    assert.deepEqual(again.bytes.length, first.bytes.length);
    figures.push(`first 3dm ${first.lastFile.ms.toFixed(0)} ms with rhino3dm's load, again ${again.lastFile.ms.toFixed(0)} ms, ${first.bytes.length} bytes`);
  });

  it('a bad tolerance is a message, nothing is downloaded; an unreachable one names the patch', async () => {
    for (const bad of ['abc', '-1', '0', '1e-400', '0x10', '1e5e']) {
      await page.locator(toleranceInput).fill(bad);
      const r = await refused(page, 'step', downloads);
      assert.equal(r.downloads, 0, `${bad}: downloaded`);
      const want = `cannot export STEP: InvalidField: tolerance "${bad}": a positive number in scene units (e.g. 1e-4), or empty for the default (1e-6 of the scene's diagonal)`;
      assert.equal(r.lastFile.error, want);
      assert.equal(r.line, want);
      assert.match(r.lineClass, /\berror\b/);
      assert.equal(r.status, want);
      assert.match(r.statusClass, /\berror\b/);
    }
    await page.locator(toleranceInput).fill('1e-300');
    const t0 = Date.now();
    const r = await refused(page, '3dm', downloads);
    assert.equal(r.downloads, 0);
    assert.match(r.line, /^cannot export 3dm: TooLarge: patch 'blend': the fit reached a certified deviation of \S+ \(tolerance 1e-300\)/);
    figures.push(`TooLarge at 1e-300 in ${Date.now() - t0} ms`);
    await shoot(page, 'cad-export-error.png');
    // A tolerance typed: the file's.
    await page.locator(toleranceInput).fill(' 1e-4 ');
    const loose = await download(page, 'step');
    assert.equal(loose.lastFile.tolerance, 1e-4);
    assert.match(loose.bytes.toString('latin1'), /LENGTH_MEASURE\(0\.0001\)/);
    figures.push(`STEP at 1e-4 ${loose.bytes.length} bytes`);
    await page.locator(toleranceInput).fill('');
  });

  it('names in messages are text, never markup', async () => {
    const scene = JSON.parse(fs.readFileSync(EXAMPLE, 'utf8'));
    const name = '<img src=x onerror="window.__xss=1">';
    scene.patches[0].name = name;
    for (const p of scene.patches.slice(1)) p.meets.patch = name;
    const count = await page.evaluate(() => window.__pdesurf.solveCount);
    await page.locator('[data-file="input"]').setInputFiles({ name: 'markup.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(scene)) });
    assert.equal((await solvedAfter(page, count)).lastError, null);
    await page.locator(toleranceInput).fill('1e-300');
    const r = await refused(page, 'step', downloads);
    assert.ok(r.line.includes(`TooLarge: patch '${name}'`), r.line);
    assert.ok(!r.lineHtml.includes('<img'), r.lineHtml);
    assert.equal(await page.locator(`${cadLine} img, #status img`).count(), 0);
    assert.equal(await page.evaluate(() => window.__xss), undefined);
    await page.locator(toleranceInput).fill('');
    const back = await page.evaluate(() => window.__pdesurf.solveCount);
    await page.evaluate((id) => { location.hash = `#example=${id}`; }, ID);
    assert.equal((await solvedAfter(page, back)).exampleId, ID);
  });

  it('an edit during an export waits for it; both land and the page keeps working', async () => {
    const count = await page.evaluate(() => window.__pdesurf.solveCount);
    const [d] = await Promise.all([
      page.waitForEvent('download', { timeout: 120_000 }),
      // The grid changes once the export is in the worker (its "fitting" line is written in
      // the same task that posts it).
      page.evaluate(([buttonSel, lineSel]) => {
        const line = document.querySelector(lineSel);
        const seen = new MutationObserver(() => {
          if (!line.textContent.startsWith('fitting')) return;
          seen.disconnect();
          window.__pdesurf.requestGrid(40, 40);
        });
        seen.observe(line, { childList: true, characterData: true, subtree: true });
        document.querySelector(buttonSel).click();
      }, [button('step'), cadLine]),
    ]);
    assert.equal(d.suggestedFilename(), `${ID}.step`);
    const after = await solvedAfter(page, count);
    assert.equal(after.lastError, null);
    assert.equal(await page.evaluate(() => window.__pdesurf.lastSolve.nu), 40);
    assert.equal(await page.evaluate(() => window.__pdesurf.solverRestarts()), 0);
  });

  it('on a phone (390×844, touch) the File folder fits the screen after an export', async () => {
    const phone = await h.open(`/app/#example=${ID}`, { viewport: { width: 390, height: 844 } });
    // A phone's coarse pointer: lil-gui's touch-sized rows (28 px, more spacing).
    const cdp = await h.context.newCDPSession(phone);
    await cdp.send('Emulation.setTouchEmulationEnabled', { enabled: true, maxTouchPoints: 5 });
    assert.equal(await phone.evaluate(() => matchMedia('(pointer: coarse)').matches), true);
    await phone.locator('[data-action="panel"]').click();
    await openFolder(phone);
    const [d] = await Promise.all([phone.waitForEvent('download', { timeout: 120_000 }), phone.locator(button('step')).click()]);
    assert.equal(d.suggestedFilename(), `${ID}.step`);
    await phone.waitForFunction((s) => document.querySelector(s).textContent.startsWith('STEP: 3 faces'), cadLine);
    // The folder's title at the top of the sheet: the whole folder in view.
    await phone.evaluate((s) => {
      const panel = document.getElementById('panel');
      const children = panel.querySelector(':scope > .children') ?? panel;
      const folder = document.querySelector(s);
      children.scrollTop += folder.getBoundingClientRect().top - children.getBoundingClientRect().top;
    }, folderSel);
    await phone.waitForTimeout(100);
    const fitIn = await phone.evaluate((s) => {
      const panel = document.getElementById('panel').getBoundingClientRect();
      const f = document.querySelector(s).getBoundingClientRect();
      const widest = Math.max(...[...document.querySelectorAll(`${s} *`)].map((e) => e.getBoundingClientRect().right));
      return { folder: f.toJSON(), panel: panel.toJSON(), widest, vw: innerWidth, vh: innerHeight };
    }, folderSel);
    await shoot(phone, 'cad-export-phone.png');
    assert.ok(fitIn.widest <= fitIn.vw + 0.5, `wider than the screen: ${JSON.stringify(fitIn)}`);
    assert.ok(fitIn.folder.top >= fitIn.panel.top - 0.5 && fitIn.folder.bottom <= Math.min(fitIn.panel.bottom, fitIn.vh) + 0.5,
      `the folder does not fit the sheet: ${JSON.stringify(fitIn)}`);
    await phone.close();
  });

  // The aeroplane's fit takes seconds: the bar follows the patches and cancel ends it, at
  // 1280×800 and on a phone; nothing is written, and the page solves again after.
  for (const [label, viewport] of [['desktop', { width: 1280, height: 800 }], ['phone', { width: 390, height: 844 }]]) {
    it(`a long STEP export shows its progress and cancels (${label}, ${viewport.width}×${viewport.height})`, async () => {
      const p = await h.open('/app/#example=you2004-fig8d', { viewport });
      let saved = 0;
      p.on('download', () => { saved++; });
      assert.equal(await p.evaluate(() => window.__pdesurf.lastError), null);
      if (viewport.width < 600) await p.locator('[data-action="panel"]').click();
      await openFolder(p);
      await p.locator(`${folderSel} [data-file="step"] button`).click();
      const bar = `${folderSel} [data-file="cad-progress"]`;
      await p.waitForFunction((s) => { const b = document.querySelector(`${s} progress`); return b && !b.closest('[hidden]') && b.value > 0; }, bar, { timeout: 60_000 });
      const line = await p.locator(cadLine).textContent();
      assert.match(line, /^fitting STEP: \d+ of 22 patches \(\S+\)$/);
      await p.locator(bar).scrollIntoViewIfNeeded();
      const box = await p.locator(bar).boundingBox();
      assert.ok(box.x >= 0 && box.x + box.width <= viewport.width + 0.5, JSON.stringify(box));
      await shoot(p, `cad-export-progress-${label}.png`);
      await p.locator(`${folderSel} [data-file="cad-cancel"]`).click();
      await p.waitForFunction((s) => document.querySelector(s).textContent === 'STEP export cancelled', cadLine);
      assert.equal(await p.locator(bar).isVisible(), false, 'the bar stays after the cancel');
      assert.deepEqual(await p.evaluate(() => window.__pdesurf.lastFile), { action: 'step', cancelled: true });
      // The solver's worker was ended: the next solve starts a new one and succeeds.
      const before = await p.evaluate(() => window.__pdesurf.solveCount);
      await p.evaluate(() => { location.hash = '#example=you2004-fig4a'; });
      const after = await solvedAfter(p, before);
      assert.equal(after.lastError, null);
      assert.equal(after.exampleId, 'you2004-fig4a');
      assert.equal(saved, 0, 'a cancelled export wrote a file');
      await p.close();
    });
  }

  it('logged no console error, page error, failed request or CSP violation', async () => {
    assert.deepEqual(await page.evaluate(() => window.__cspViolations), []);
    assert.deepEqual(h.problems, []);
  });
});
