// Keyboard and help, and the small things of issue 11: sliders reached with Tab and moved
// with the arrow keys (one solve per press), number boxes that show 8 significant digits
// without cutting them, the ? overlay listing the shortcuts and linking the docs (served),
// a damaged link left in the address bar, distinct gallery labels, and an example that
// reopens on the default grid.
//   node --test tests/browser/keyboard-help.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { skip, startHarness, hooks, solvedAfter, shoot, exampleIndex } from './harness.mjs';

describe('keyboard, help and the small things', { skip }, () => {
  let h, page;
  before(async () => {
    h = await startHarness();
    page = await h.open('/web/#example=you2004-fig2a');
  });
  after(async () => {
    await h?.close();
  });

  it('every slider is reached with Tab and adjusted with the arrow keys', async () => {
    const sliders = await page.locator('#panel .slider').count();
    assert.ok(sliders >= 15, `${sliders} sliders`);
    assert.equal(await page.locator('#panel .slider[tabindex="0"][role="slider"]').count(), sliders);
    // Tab from the top of the page until the first parameter slider has the focus.
    await page.evaluate(() => document.activeElement?.blur());
    let found = false;
    for (let k = 0; k < 200 && !found; k++) {
      await page.keyboard.press('Tab');
      found = await page.evaluate(() => document.activeElement?.matches('#panel [data-param="r0"] .slider'));
    }
    assert.ok(found, 'Tab never reached the r0 slider');
    const input = page.locator('#panel [data-param="r0"] input');
    const v0 = Number(await input.inputValue());
    const before = await hooks(page);
    await page.keyboard.press('ArrowRight');
    const after1 = await solvedAfter(page, before.solveCount);
    const v1 = Number(await input.inputValue());
    const [min, max] = await page.evaluate(() => {
      const s = document.querySelector('#panel [data-param="r0"] .slider');
      return [Number(s.getAttribute('aria-valuemin')), Number(s.getAttribute('aria-valuemax'))];
    });
    // A hundredth of the range, on lil-gui's grid of range / 1000.
    assert.ok(Math.abs(v1 - v0 - (max - min) / 100) <= (max - min) / 2000 + 1e-12, `${v0} -> ${v1} over [${min}, ${max}]`);
    assert.notEqual(after1.checksum, before.checksum);
    await page.keyboard.press('End');
    await solvedAfter(page, after1.solveCount);
    assert.equal(Number(await input.inputValue()), max);
    assert.equal(Number(await page.locator('#panel [data-param="r0"] .slider').getAttribute('aria-valuenow')), max);
    await shoot(page, 'keyboard-slider.png');
    const n = (await hooks(page)).solveCount;
    await page.keyboard.press('Home');
    await solvedAfter(page, n);
    assert.equal(Number(await input.inputValue()), min);
  });

  it('number boxes show 8 significant digits, uncut', async () => {
    const input = page.locator('#panel [data-param="r0p"] input');
    for (const [typed, shown] of [['0.000102', '0.000102'], [String(Math.E), '2.7182818'], ['-0.123456789', '-0.12345679']]) {
      await input.fill(typed);
      await input.press('Enter');
      await page.locator('#viewport canvas').focus(); // the box shows its formatted value once it loses the focus
      assert.equal(await input.inputValue(), shown);
      const cut = await input.evaluate((el) => el.scrollWidth > el.clientWidth);
      assert.equal(cut, false, `${shown} does not fit its box`);
    }
    await shoot(page, 'keyboard-number-digits.png');
  });

  it('? opens the help with the shortcuts and the docs, Escape closes it; not while typing', async () => {
    await page.locator('#viewport canvas').focus();
    await page.keyboard.press('?');
    const help = page.locator('#help');
    assert.ok(await help.isVisible());
    const text = await help.textContent();
    for (const s of ['fit the view', 'undo', 'redo', 'orbit', 'zoom', 'double-click']) assert.ok(text.includes(s), s);
    const links = await help.locator('a').evaluateAll((as) => as.map((a) => a.getAttribute('href')));
    assert.ok(links.length >= 3);
    for (const href of links) {
      const r = await page.request.get(new URL(href, page.url()).href);
      assert.equal(r.status(), 200, href);
    }
    await shoot(page, 'help.png');
    await page.keyboard.press('Escape');
    assert.equal(await help.isVisible(), false);
    await page.locator('[data-action="help"]').click();
    assert.ok(await help.isVisible());
    await page.locator('#help [data-help="close"]').click();
    assert.equal(await help.isVisible(), false);
    const field = page.locator('#panel [data-param-new="name"] input');
    await field.focus();
    await page.keyboard.press('?');
    assert.equal(await help.isVisible(), false);
    assert.equal(await field.inputValue(), '?');
    await field.fill('');
  });

  it('Esc closes the Controls sheet even from a field inside it', async () => {
    const phone = await h.open('/web/#example=you2004-fig2a', { viewport: { width: 390, height: 844 } });
    await phone.locator('[data-action="panel"]').click();
    await phone.locator('#panel [data-param="r0"] input').focus();
    await phone.keyboard.press('Escape');
    assert.equal(await phone.locator('#panel').isVisible(), false);
    await phone.close();
  });

  it('the help fits a phone', async () => {
    const phone = await h.open('/web/#example=you2004-fig2a', { viewport: { width: 390, height: 844 } });
    await phone.locator('[data-action="help"]').click();
    const box = await phone.locator('#help').boundingBox();
    assert.ok(box.x >= 0 && box.x + box.width <= 390 && box.y >= 0 && box.y + box.height <= 844, JSON.stringify(box));
    await shoot(phone, 'help-phone.png');
    await phone.close();
  });

  it('a damaged link stays in the address bar while the default example shows', async () => {
    const damaged = '#s=1.thisisnotadeflatedscene';
    const p = await h.open(`/web/${damaged}`);
    const got = await hooks(p);
    assert.equal(got.exampleId, exampleIndex()[0].id);
    assert.match(got.notice, /cannot open the link/);
    assert.equal(await p.evaluate(() => location.hash), damaged);
    await p.close();
  });

  it('gallery labels are distinct within each paper', async () => {
    const seen = new Map();
    for (const e of exampleIndex()) {
      const key = `${e.source.paper}|${e.source.figure}`;
      assert.ok(!seen.has(key), `${e.id} and ${seen.get(key)} both read ${key}`);
      seen.set(key, e.id);
    }
    assert.equal(await page.locator('#gallery [data-example="wu2015-fig1a"] .gallery-figure').textContent(), 'Fig. 1, top');
  });

  it('reopening an example resets its grid too', async () => {
    await page.locator('#panel [data-folder="grid"], #panel .lil-gui:has([data-grid])').first().locator('> .title').click().catch(() => {});
    const nu = page.locator('#panel [data-grid="nu"] input');
    // Counted before the edit: a loaded machine may solve on the typed value before Enter.
    const n = (await hooks(page)).solveCount;
    await nu.fill('100');
    await nu.press('Enter');
    await solvedAfter(page, n);
    assert.equal(await page.evaluate(() => window.__pdesurf.lastSolve.nu), 100);
    const m = (await hooks(page)).solveCount;
    await page.locator('#gallery [data-example="you2004-fig2a"]').click();
    await solvedAfter(page, m);
    assert.equal(await page.evaluate(() => window.__pdesurf.lastSolve.nu), 64);
    assert.equal(await nu.inputValue(), '64');
  });

  it('logged no console error, page error or failed request', () => {
    assert.deepEqual(h.problems, []);
  });
});
