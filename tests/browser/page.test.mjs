// End-to-end test of the modeller page in headless Chromium (Debian's, through
// playwright-core): the page draws, sliders re-solve, solver errors are shown while
// the last good surfaces stay, operator orders and methods can be chosen, the gallery
// and #example= links open examples, and nothing logs an error. Controls are found by
// their data-* hooks: data-param="<name>", data-operator="<axis>.<coefficient>",
// data-order="<axis>", data-method / data-method-used="<patch>" (web/ui/*-controls.js),
// data-example="<id>" (web/ui/gallery.js).
//   node --test tests/browser/
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { skip, startHarness, exampleIndex, hooks, solvedAfter, shoot, viewStats, sameChecksum, REPO } from './harness.mjs';

describe('modeller page', { skip }, () => {
  let h, page;
  before(async () => {
    h = await startHarness();
  });
  after(async () => {
    await h?.close();
  });

  it('opens on the first example and draws both surface colours', async () => {
    const index = exampleIndex();
    page = await h.open('/');
    const drawn = await hooks(page);
    assert.equal(drawn.lastError, null, `page reported: ${drawn.lastError}`);
    assert.equal(drawn.ready, true);
    assert.equal(drawn.exampleId, index[0].id);
    assert.ok(drawn.vertexCount > 0 && Number.isFinite(drawn.checksum) && drawn.checksum > 0);
    // The production build when scripts/build-web.mjs made one (scripts/test does), else the sources.
    const built = fs.existsSync(path.join(REPO, 'build', 'web', 'index.html'));
    assert.equal(new URL(page.url()).pathname, built ? '/app/' : '/web/');
    assert.equal(new URL(page.url()).hash, `#example=${encodeURIComponent(index[0].id)}`);

    const img = await shoot(page, 'modeller.png');
    const stats = await viewStats(page, img);
    assert.ok(stats.fraction > 0.03, `canvas looks blank: ${JSON.stringify(stats)}`);
    assert.ok(stats.orange > 200, `no blend-coloured pixels: ${JSON.stringify(stats)}`);
    assert.ok(stats.blue > 200, `no primary-surface-coloured pixels: ${JSON.stringify(stats)}`);
  });

  it('re-solves when a parameter slider is dragged', async () => {
    const slider = page.locator('#panel [data-param] .slider').first();
    const box = await slider.boundingBox();
    assert.ok(box, 'no parameter slider in the panel');
    const before = await hooks(page);
    // Click two different spots so at least one of them moves the value.
    await page.mouse.click(box.x + box.width * 0.3, box.y + box.height / 2);
    let now = await solvedAfter(page, before.solveCount);
    if (now.checksum === before.checksum) {
      await page.mouse.click(box.x + box.width * 0.7, box.y + box.height / 2);
      now = await solvedAfter(page, now.solveCount);
    }
    assert.equal(now.lastError, null);
    assert.notEqual(now.checksum, before.checksum, 'moving a parameter did not change the surfaces');
  });

  it('shows a solver error and keeps the last good surfaces', async () => {
    const input = page.locator('#panel [data-operator="x.b"] input').first();
    const original = await input.inputValue();
    const before = await hooks(page);
    await input.fill('0'); // b = 0 makes the operator degenerate
    const failed = await solvedAfter(page, before.solveCount);
    assert.ok(failed.lastError, 'b = 0 did not produce an error');
    const status = page.locator('#status');
    assert.ok(await status.isVisible());
    assert.equal(await status.textContent(), failed.lastError);
    assert.equal(failed.checksum, before.checksum, 'the last good surfaces were replaced');
    assert.equal(failed.vertexCount, before.vertexCount);
    // The operator error names no function field: none shows a message.
    assert.equal(await page.locator('#panel .expr-error:visible').count(), 0);
    const img = await shoot(page, 'modeller-error.png');
    assert.ok((await viewStats(page, img)).fraction > 0.03, 'surfaces vanished on error');

    await input.fill(original); // back to the resolved value: the same surfaces again
    const healed = await solvedAfter(page, failed.solveCount);
    assert.equal(healed.lastError, null);
    assert.ok(sameChecksum(healed.checksum, before.checksum),
      `restoring b gave checksum ${healed.checksum}, expected ${before.checksum}`);
  });

  it('changes a coordinate\'s order, with its function fields, and restores its boundary slots on the way back', async () => {
    await page.close();
    page = await h.open('/web/#example=you2004-fig2a');
    const blend = page.locator('#panel [data-patch="blend"]');
    const order = blend.locator('[data-order="z"] select');
    const zFields = page.locator('#panel [data-functions="blend"] [data-axis="z"] [data-expr]');
    const before = await hooks(page);
    assert.equal(before.exampleId, 'you2004-fig2a');
    assert.equal(await order.inputValue(), '4');
    assert.equal(await blend.locator('[data-operator="z.b"]').count(), 1);
    assert.equal(await zFields.count(), 5, 'order 4: u0, u0\', u1, u1\' and the force');

    await order.selectOption('2'); // z: order 2, u0/u1 keep only the position condition
    const second = await solvedAfter(page, before.solveCount);
    assert.equal(second.lastError, null, `order 2 failed: ${second.lastError}`);
    assert.notEqual(second.checksum, before.checksum, 'order 2 did not change the surfaces');
    assert.equal(await blend.locator('[data-operator="z.b"]').count(), 0);
    assert.equal(await blend.locator('[data-operator="z.s"] input').inputValue(), '1');
    assert.equal(await blend.locator('[data-operator="z.t"] input').inputValue(), '1');
    assert.equal(await zFields.count(), 3, 'order 2: u0, u1 and the force');
    await shoot(page, 'modeller-order2.png');

    await order.selectOption('4'); // defaults b = d = 1, c = 2 and the stashed tangent conditions
    const back = await solvedAfter(page, second.solveCount);
    assert.equal(back.lastError, null);
    assert.equal(back.checksum, before.checksum, 'order 4 again did not give the original surfaces');
    for (const name of ['b', 'c', 'd']) assert.equal(await blend.locator(`[data-operator="z.${name}"]`).count(), 1);
    assert.equal(await zFields.count(), 5);
    assert.equal(await page.locator('#panel [data-expr="patches[0].boundary.z.u1[1]"] input').inputValue(), 'h1p');
  });

  it('offers the solver\'s methods and shows the one used', async () => {
    const blend = page.locator('#panel [data-patch="blend"]');
    const options = await blend.locator('[data-method="blend"] select option').allTextContents();
    for (const m of ['auto', 'closed']) assert.ok(options.includes(m), `methods offered: ${options}`);
    assert.equal(await blend.locator('[data-method="blend"] select').inputValue(), 'auto');
    assert.equal(await blend.locator('[data-method-used="blend"] input').inputValue(), 'closed');
  });

  it('re-solves with a chosen method, and "auto" brings back the default', async () => {
    const select = page.locator('#panel [data-method="blend"] select');
    const before = await hooks(page);
    await select.selectOption('closed'); // writes "method": "closed" into the scene
    const chosen = await solvedAfter(page, before.solveCount);
    assert.equal(chosen.lastError, null, `choosing "closed" failed: ${chosen.lastError}`);
    assert.equal(chosen.checksum, before.checksum); // auto picks the closed form here
    await select.selectOption('auto'); // removes the field again
    const auto = await solvedAfter(page, chosen.solveCount);
    assert.equal(auto.lastError, null);
    assert.equal(auto.checksum, before.checksum);
  });

  it('lists every example grouped by paper and opens three of them by clicking', async () => {
    const index = exampleIndex();
    const papers = [...new Set(index.map((e) => e.source.paper))];
    assert.deepEqual(await page.locator('#gallery .gallery-paper').allTextContents(), papers);
    assert.equal(await page.locator('#gallery [data-example]').count(), index.length);
    // One from each paper where possible, none of them the open one.
    const picks = papers.map((p) => index.find((e) => e.source.paper === p && e.id !== 'you2004-fig2a')).slice(0, 3);
    const sums = new Set([(await hooks(page)).checksum]);
    for (const entry of picks) {
      const before = await hooks(page);
      const item = page.locator(`#gallery [data-example="${entry.id}"]`);
      await item.click();
      await page.waitForFunction((id) => window.__pdesurf.exampleId === id, entry.id, { timeout: 20_000 });
      const now = await solvedAfter(page, before.solveCount);
      assert.equal(now.lastError, null, `${entry.id}: ${now.lastError}`);
      assert.equal(new URL(page.url()).hash, `#example=${encodeURIComponent(entry.id)}`);
      assert.equal(await item.getAttribute('aria-current'), 'true');
      assert.ok((await page.locator('#scene-title').textContent()).includes(entry.title));
      const img = await shoot(page, `gallery-${entry.id}.png`);
      const stats = await viewStats(page, img);
      assert.ok(stats.fraction > 0.03, `${entry.id} looks blank: ${JSON.stringify(stats)}`);
      assert.ok(!sums.has(now.checksum), `${entry.id} drew the same surfaces as an earlier example`);
      sums.add(now.checksum);
    }
    // The open example's description, as text, under its entry.
    assert.equal(await page.locator('#gallery .gallery-description').count(), 1);
  });

  it('collapses the gallery to give the view the space, and brings it back', async () => {
    const toggle = page.locator('#gallery .gallery-toggle');
    const width = () => page.evaluate(() => document.getElementById('viewport').getBoundingClientRect().width);
    const open = await width();
    await toggle.click();
    assert.equal(await toggle.getAttribute('aria-expanded'), 'false');
    assert.equal(await page.locator('#gallery .gallery-list').isVisible(), false);
    await page.waitForFunction((w) => document.getElementById('viewport').getBoundingClientRect().width > w, open);
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    const img = await shoot(page, 'gallery-closed.png');
    assert.ok((await viewStats(page, img)).fraction > 0.03, 'the view is blank after resizing');
    await toggle.click();
    assert.equal(await width(), open);
    assert.ok(await page.locator('#gallery .gallery-list').isVisible());
  });

  it('opens examples through an edited hash and a fresh #example= link', async () => {
    const index = exampleIndex();
    const first = index[0].id;
    const before = await hooks(page);
    await page.evaluate((id) => { location.hash = 'example=' + encodeURIComponent(id); }, first);
    await page.waitForFunction((id) => window.__pdesurf.exampleId === id, first, { timeout: 20_000 });
    assert.equal((await solvedAfter(page, before.solveCount)).lastError, null);

    await page.close();
    page = await h.open(`/web/#example=${encodeURIComponent(index[1].id)}`);
    assert.equal((await hooks(page)).exampleId, index[1].id);
  });

  it('shows an unknown example id from a link as text, not markup', async () => {
    const evil = '<img src=x onerror="window.__pwned=1">';
    await page.close();
    page = await h.open(`/web/#example=${encodeURIComponent(evil)}`);
    const text = await page.locator('#status').textContent();
    assert.ok(text.includes(evil), `status was: ${text}`);
    assert.equal(await page.evaluate(() => document.querySelectorAll('img').length), 0);
    assert.equal(await page.evaluate(() => window.__pwned), undefined);
  });

  it('logged no console error, page error or failed request', () => {
    assert.deepEqual(h.problems, []);
  });
});
