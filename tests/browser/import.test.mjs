// Opening a scene file (web/features/files.js, web/import/): by the picker (the hidden input
// data-file="input") and by dropping it on the page (a DataTransfer built in the page). A good
// file opens like an example or a link (its title, no example id, the link in the hash once
// solved); the page's own export opens back to the same surfaces; a scene too large for a link
// opens, says so and leaves no older link in the hash. Every bad file (not JSON,
// a list, no patches, repeated keys, too deep, too large, not UTF-8, a scene the solver
// refuses) says "cannot open <name>: <code>: <message>" and keeps what was shown: checksum,
// example id, URL hash, camera and the panel.
//   PDESURF_WASM_DIR=build/wasm node --test tests/browser/import.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { skip, startHarness, hooks, shoot, viewStats, solvedAfter, sameChecksum, ROOT } from './harness.mjs';

const exampleText = (id) => fs.readFileSync(path.join(ROOT, 'examples', `${id}.json`), 'utf8');
const MiB = 1 << 20;

describe('opening scene files', { skip }, () => {
  let h, page;
  const statusText = () => page.locator('#status').textContent();
  const title = () => page.locator('#scene-title').textContent();
  const pick = (name, text) => page.locator('[data-file="input"]').setInputFiles({ name, mimeType: 'application/json', buffer: Buffer.isBuffer(text) ? text : Buffer.from(text) });

  // Drag a file over the page and drop it, as a user's drag from the desktop would.
  async function drop(name, text, { stopOver = false } = {}) {
    await page.evaluate(([n, t, stop]) => {
      const dt = new DataTransfer();
      dt.items.add(new File([t], n, { type: 'application/json' }));
      const target = document.getElementById('viewport');
      target.dispatchEvent(new DragEvent('dragenter', { dataTransfer: dt, bubbles: true, cancelable: true }));
      target.dispatchEvent(new DragEvent('dragover', { dataTransfer: dt, bubbles: true, cancelable: true }));
      if (!stop) target.dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
    }, [name, text, stopOver]);
  }

  async function snapshot() {
    return { ...(await hooks(page)), hash: await page.evaluate(() => location.hash), title: await title(),
      panel: await page.locator('#panel [data-expr], #panel [data-param]').count() };
  }
  function assertKept(now, was) {
    assert.ok(sameChecksum(now.checksum, was.checksum), 'the drawn surfaces changed');
    assert.equal(now.exampleId, was.exampleId);
    assert.equal(now.hash, was.hash);
    assert.equal(now.title, was.title);
    assert.equal(now.panel, was.panel, 'the panel changed');
    // Brought back through the controls (viewer.setCamera): equal to rounding.
    const flat = (c) => [...c.position, ...c.target];
    flat(now.camera).forEach((x, k) => assert.ok(Math.abs(x - flat(was.camera)[k]) < 1e-9, `the camera moved: ${JSON.stringify(now.camera)}`));
  }
  // A refusal before any solve: the status line changes, nothing else.
  async function refused(name, open) {
    await page.evaluate(() => { document.getElementById('status').textContent = ''; });
    await open();
    await page.waitForFunction(() => /^cannot open /.test(document.getElementById('status').textContent));
    return statusText();
  }

  before(async () => {
    h = await startHarness();
    page = await h.open('/web/#example=you2004-fig2a');
    assert.equal((await hooks(page)).lastError, null);
  });
  after(async () => {
    await h?.close();
  });

  it('a file picked opens its scene: title, no example id, the same surfaces as the example, a link in the hash', async () => {
    const reference = await h.open('/web/#example=wu2015-fig3');
    const want = await hooks(reference);
    await reference.close();
    const before = await hooks(page);
    await pick('hat.json', exampleText('wu2015-fig3'));
    const opened = await solvedAfter(page, before.solveCount);
    assert.equal(opened.lastError, null);
    assert.equal(opened.exampleId, null);
    assert.ok(sameChecksum(opened.checksum, want.checksum), 'not the example\'s surfaces');
    assert.equal(await title(), 'Hat with a wavy edge under a discrete normal field (ridge) (hat.json)');
    assert.equal(await page.locator('#gallery .active, #gallery [aria-current="true"]').count(), 0, 'an example is still marked');
    await page.waitForFunction(() => location.hash.startsWith('#s=1.'), null, { timeout: 10_000 });
    const img = await shoot(page, 'import-opened.png');
    assert.ok((await viewStats(page, img)).fraction > 0.03);
  });

  it('the page\'s own scene JSON opens back to the same surfaces', async () => {
    let before = await hooks(page);
    await page.evaluate(() => { location.hash = '#example=you2004-fig2a'; });
    const example = await solvedAfter(page, before.solveCount);
    const [d] = await Promise.all([page.waitForEvent('download'), page.evaluate(() => document.querySelector('#panel [data-file="json"] button').click())]);
    const text = fs.readFileSync(await d.path(), 'utf8');
    before = await hooks(page);
    await pick(d.suggestedFilename(), text);
    const back = await solvedAfter(page, before.solveCount);
    assert.equal(back.lastError, null);
    assert.ok(sameChecksum(back.checksum, example.checksum));
    assert.equal(back.vertexCount, example.vertexCount);
  });

  it('a file dropped on the page opens; the page is highlighted while it is dragged over', async () => {
    let before = await hooks(page);
    await page.evaluate(() => { location.hash = '#example=you2004-fig2a'; });
    await solvedAfter(page, before.solveCount);
    await drop('c2.json', exampleText('zhang-c2-ex1'), { stopOver: true });
    assert.equal(await page.evaluate(() => document.body.classList.contains('file-drop')), true);
    await shoot(page, 'import-drag-over.png');
    before = await hooks(page);
    await drop('c2.json', exampleText('zhang-c2-ex1'));
    const opened = await solvedAfter(page, before.solveCount);
    assert.equal(await page.evaluate(() => document.body.classList.contains('file-drop')), false);
    assert.equal(opened.lastError, null);
    assert.equal(opened.exampleId, null);
    assert.match(await title(), /\(c2\.json\)$/);
    await shoot(page, 'import-dropped.png');
    // A drag that carries no file is the browser's, not ours.
    await page.evaluate(() => {
      const dt = new DataTransfer();
      dt.setData('text/plain', 'hello');
      window.dispatchEvent(new DragEvent('dragenter', { dataTransfer: dt, bubbles: true, cancelable: true }));
    });
    assert.equal(await page.evaluate(() => document.body.classList.contains('file-drop')), false);
  });

  it('a scene past a link\'s 1 MiB (an imported CAD part\'s size) opens and solves; the page says it is kept as a file, and the hash names no older scene', async () => {
    // Two 110 × 110 bicubic sheets: 24 200 control points at full precision, ~1.4 MB of text.
    const n = 110, knots = [0, 0, 0, 0, ...Array.from({ length: n - 4 }, (_, k) => (k + 1) / (n - 3)), 1, 1, 1, 1];
    const sheet = (name, dz) => ({ name, kind: 'surface', nurbs: { degree: [3, 3], knots: [knots, knots],
      points: Array.from({ length: n }, (_, i) => Array.from({ length: n }, (_, j) => [i / Math.PI, j / Math.E, dz + 0.3 * Math.sin(i / 7) * Math.cos(j / 9)])) } });
    const text = JSON.stringify({ format: 'pdesurf-scene', version: 4, title: 'big sheets', patches: [sheet('lower', 0), sheet('upper', 5)] });
    assert.ok(text.length > 1.2 * MiB, `${text.length} characters`);
    const before = await hooks(page);
    await pick('big-sheet.json', text);
    const opened = await solvedAfter(page, before.solveCount);
    assert.equal(opened.lastError, null);
    await page.waitForFunction(() => /too large for a link/.test(document.getElementById('status').textContent), null, { timeout: 20_000 });
    assert.match(await statusText(), /; the scene is too large for a link \(\d+ bytes, at most 1048576\): keep it with File → export scene JSON$/);
    assert.equal(await page.evaluate(() => location.hash), '', 'the hash names no older scene');
    assert.equal(await page.locator('#panel [data-share="length"] input').inputValue(), 'too large for a link');
    await shoot(page, 'import-too-large-for-a-link.png');
  });

  describe('a bad file keeps the scene shown', () => {
    let was;
    before(async () => {
      const before = await hooks(page);
      await page.evaluate(() => { location.hash = '#example=you2004-fig2a'; });
      await solvedAfter(page, before.solveCount);
      // An edited state: the hash holds its link, the example id stays, a field differs from the file's.
      const b2 = await hooks(page);
      await page.locator('#panel [data-expr="patches[0].boundary.x.u0[1]"] input').fill('r0p*cos(v)*1.1');
      await solvedAfter(page, b2.solveCount);
      await page.waitForFunction(() => location.hash.startsWith('#s=1.'), null, { timeout: 10_000 });
      was = await snapshot();
      assert.equal(was.exampleId, 'you2004-fig2a');
    });

    const good = JSON.parse(exampleText('you2004-fig2a'));
    const cases = [
      ['not-json.json', '{"patches": [', /^cannot open not-json\.json: ParseError: the file is not JSON \(/],
      ['list.json', '[1, 2, 3]', /^cannot open list\.json: InvalidField: the file holds a list, not a scene/],
      ['no-patches.json', '{"title": "x"}', /^cannot open no-patches\.json: InvalidField: the file holds no scene: a scene has a "patches" list$/],
      ['twice.json', '{"patches": [], "patches": []}', /^cannot open twice\.json: ParseError: the file is not a valid scene: the key "patches" appears twice in one object$/],
      ['deep.json', `{"patches": ${'['.repeat(40)}${']'.repeat(40)}}`, /^cannot open deep\.json: TooLarge: the file is nested deeper than 32 levels$/],
      ['big.json', `{"patches": [], "notes": "${'x'.repeat(16 * MiB)}"}`, /^cannot open big\.json: TooLarge: the file has \d+ bytes; a scene file has at most 16777216 \(16 MiB\)$/],
      ['latin1.json', Buffer.from([0x7b, 0x22, 0xe9, 0x22, 0x3a, 0x31, 0x7d]), /^cannot open latin1\.json: ParseError: the file is not UTF-8 text$/],
    ];
    for (const [name, text, pattern] of cases) {
      it(`${name}: refused with its named error, by the picker and by a drop`, async () => {
        assert.match(await refused(name, () => pick(name, text)), pattern);
        assertKept(await snapshot(), was);
        if (name === 'not-json.json') await shoot(page, 'import-refused.png');
        const dropped = await refused(name, () => drop(name, Buffer.isBuffer(text) ? text.toString('latin1') : text));
        if (name !== 'latin1.json') assert.match(dropped, pattern); // a string in the page is UTF-16: re-encoded as UTF-8
        assertKept(await snapshot(), was);
        assert.equal((await hooks(page)).notice, await statusText());
      });
    }

    it('a scene whose first solve fails: the solver\'s error, then the scene before comes back as it was', async () => {
      const bad = structuredClone(good);
      bad.patches[0].boundary.x.u0[1] = 'r0p*cso(v)';
      const before = await hooks(page);
      await page.evaluate(() => { document.getElementById('status').textContent = ''; });
      await pick('bad-expression.json', JSON.stringify(bad));
      // The file's solve fails, the previous scene is solved again.
      await page.waitForFunction((n) => window.__pdesurf.solveCount >= n + 2 && window.__pdesurf.notice, before.solveCount, { timeout: 20_000 });
      await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));
      const status = await statusText();
      assert.match(status, /^cannot open bad-expression\.json: [A-Za-z]+: .*unknown function 'cso'/);
      const now = await snapshot();
      assert.equal(now.lastError, null);
      assert.equal(now.notice, status);
      assertKept(now, was);
      assert.equal(await page.locator('#panel .expr-error:visible').count(), 0, 'a field shows the file\'s error');
      assert.equal(await page.locator('#panel [data-expr="patches[0].boundary.x.u0[1]"] input').inputValue(), 'r0p*cos(v)*1.1');
      const img = await shoot(page, 'import-error.png');
      assert.ok((await viewStats(page, img)).fraction > 0.03, 'the surfaces vanished');
    });

    it('a file named like markup is shown as text', async () => {
      const name = '<img src=x data-injected=1>.json';
      const status = await refused(name, () => pick(name, 'nope'));
      assert.ok(status.startsWith(`cannot open ${name}: ParseError`), status);
      assert.equal(await page.locator('[data-injected]').count(), 0);
      assertKept(await snapshot(), was);
    });
  });

  it('logged no console error, page error or failed request', () => {
    assert.deepEqual(h.problems, []);
  });
});
