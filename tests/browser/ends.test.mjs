// The Ends folders (web/ui/end-controls.js) on the blends-by-reference examples: they show
// the scene's ends and the conditions the solver derived; continuity, power, flip and the
// trimline re-solve; a trimline outside the surface is a named error inline while the
// surfaces stay; editing the primary surface re-derives; detach types the derived texts
// (same surface), attach gives the end back by reference, one undo takes a detach back; a
// version-2 scene's typed end can be attached; the phone layout reaches the folder. Screenshots: build/browser/ends-*.png.
// Hooks: data-ends, data-end, data-end-field, data-derived (end-controls.js), data-expr
// (expression-field.js), data-end-note (expression-folders.js), data-order (axis-controls.js).
//   PDESURF_WASM_DIR=build/wasm3 node --test tests/browser/ends.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { skip, startHarness, hooks, solvedAfter, shoot, viewStats, sameChecksum, waitReady, ROOT } from './harness.mjs';
import { encodeState } from '../../web/link/link-codec.js';

const TAU_INSIDE = 'th0 + 0.1 + 0.1*sin(2*v)'; // within the sphere's t_range [th0, pi - 0.05]
const TAU_OUTSIDE = 'th0 + 0.1*sin(2*v)'; // dips below th0: outside it

describe('ends by reference in the page', { skip }, () => {
  let h, page;
  let opened = 0;
  const end = (name) => page.locator(`#panel [data-end="${name}"]`);
  const control = (name, field) => end(name).locator(`[data-end-field="${field}"]`);
  const derived = (name, id) => end(name).locator(`[data-derived="${id}"] input`);
  const shownOption = (name, field) => control(name, field).locator('select').evaluate((s) => s.options[s.selectedIndex]?.textContent);

  // A fresh load of an example (the tests below each start from the file as it is).
  async function open(id) {
    await page.goto(`${h.base}/web/?fresh=${++opened}#example=${id}`);
    await waitReady(page);
    const state = await hooks(page);
    assert.equal(state.lastError, null);
    return state;
  }
  async function change(action) {
    const before = await hooks(page);
    await action();
    return solvedAfter(page, before.solveCount);
  }
  const choose = (name, field, label) => change(() => control(name, field).locator('select').selectOption(label));
  const derivedTexts = async (name) => {
    const out = {};
    for (const axis of ['x', 'y', 'z']) {
      out[axis] = [];
      for (let k = 0; (await derived(name, `${axis}.${k}`).count()) > 0; k++) out[axis].push(await derived(name, `${axis}.${k}`).inputValue());
    }
    return out;
  };
  async function look(name, file) {
    await end(name).scrollIntoViewIfNeeded();
    return shoot(page, file);
  }

  before(async () => {
    h = await startHarness();
    page = await h.open('/web/#example=ref-sphere-fillet');
  });
  after(async () => {
    await h?.close();
  });

  it('shows each end of the sphere fillet with the scene\'s values and the solver\'s derived text', async () => {
    await open('ref-sphere-fillet');
    assert.equal(await page.locator('#panel [data-ends="fillet"]').count(), 1);
    assert.equal(await shownOption('fillet.u0', 'surface'), 'plane');
    assert.equal(await shownOption('fillet.u1', 'surface'), 'sphere');
    assert.equal(await shownOption('fillet.u1', 'at'), 't0 (iso-line)');
    assert.equal(await shownOption('fillet.u1', 'continuity'), 'tangency (G1)');
    assert.equal(await shownOption('fillet.u1', 'scale'), 'gap');
    assert.equal(await control('fillet.u1', 'power').locator('input').inputValue(), 'p1');
    assert.equal(await control('fillet.u1', 'flip').locator('input').isChecked(), false);
    assert.equal(await control('fillet.u1', 'tau').count(), 0, 'no τ field for an iso-line');
    // X(0) = S_plane(t0, v) with a = 2.2; two conditions per coordinate at order 4.
    assert.equal(await derived('fillet.u0', 'x.0').inputValue(), '2.2*cos(v)');
    assert.match(await derived('fillet.u1', 'x.0').inputValue(), /^0\.78332\d*\*cos\(v\)$/);
    assert.equal(await end('fillet.u0').locator('[data-derived]').count(), 6);
    assert.equal(await derived('fillet.u0', 'x.0').evaluate((el) => el.readOnly), true);
    // The blend's function fields leave both ends to the Ends folder: only the forces.
    assert.equal(await page.locator('#panel [data-functions="fillet"] [data-end-note]').count(), 2);
    assert.equal(await page.locator('#panel [data-functions="fillet"] [data-expr]').count(), 3);
    assert.match(await page.locator('#panel [data-functions="fillet"] [data-end-note="u1"]').textContent(), /given by reference/);
    const img = await look('fillet.u0', 'ends-sphere.png');
    assert.ok((await viewStats(page, img)).fraction > 0.03, 'no surfaces drawn');
  });

  it('tangency → curvature re-solves at order 6 with a third derived condition', async () => {
    const original = await open('ref-sphere-fillet');
    const g2 = await choose('fillet.u1', 'continuity', 'curvature (G2)');
    assert.equal(g2.lastError, null);
    assert.ok(!sameChecksum(g2.checksum, original.checksum), 'the surface did not change');
    const order = page.locator('#panel [data-patch="fillet"] [data-order="x"] select');
    assert.equal(await order.evaluate((s) => s.options[s.selectedIndex].textContent), '6');
    assert.equal(await end('fillet.u1').locator('[data-derived]').count(), 9);
    assert.notEqual(await derived('fillet.u1', 'x.2').inputValue(), '0', 'X_uu of the sphere is not zero');
    // The tangent end gets the ruled surface's X_uu = 0 at order 6.
    assert.equal(await derived('fillet.u0', 'z.2').inputValue(), '0');
    await look('fillet.u1', 'ends-curvature.png');
  });

  it('power: an expression becomes a number with a slider; a new power re-solves', async () => {
    const original = await open('ref-sphere-fillet');
    const same = await change(() => control('fillet.u1', 'power-number').click()); // p1 = 1
    assert.equal(same.lastError, null);
    assert.ok(sameChecksum(same.checksum, original.checksum), 'p1 → its value changed the surface');
    const box = control('fillet.u1', 'power').locator('input');
    assert.equal(await box.inputValue(), '1');
    assert.equal(await control('fillet.u1', 'power').locator('.slider').count(), 1);
    const fuller = await change(() => box.fill('2.5'));
    assert.equal(fuller.lastError, null);
    assert.ok(!sameChecksum(fuller.checksum, original.checksum), 'power 2.5 drew the same surface');
    await look('fillet.u1', 'ends-power.png');
    // A power that is not finite is the solver's error beside the power's field.
    await change(() => control('fillet.u1', 'power-expression').click());
    const bad = await change(() => control('fillet.u1', 'power').locator('input').fill('1/0'));
    assert.match(bad.lastError, /patches\[0\]\.ends\.u1\.power: expression '1\/0' is not finite/);
    assert.ok(await control('fillet.u1', 'power').locator('.expr-error').isVisible());
    await change(() => control('fillet.u1', 'power').locator('input').fill('2.5'));
    await change(() => control('fillet.u1', 'power-number').click());
    // Through an expression and back to a number: still the same surface.
    const again = await hooks(page);
    assert.equal(await control('fillet.u1', 'power').locator('input').inputValue(), '2.5');
    assert.equal(again.lastError, null);
    assert.ok(sameChecksum(again.checksum, fuller.checksum));
  });

  it('flip reverses the direction across the join', async () => {
    const original = await open('ref-sphere-fillet');
    const flipped = await change(() => control('fillet.u1', 'flip').locator('input').check());
    assert.equal(flipped.lastError, null);
    assert.ok(!sameChecksum(flipped.checksum, original.checksum));
    assert.match(await derived('fillet.u1', 'x.1').inputValue(), /^-/, 'X_u did not change sign');
    await look('fillet.u1', 'ends-flip.png');
    const back = await change(() => control('fillet.u1', 'flip').locator('input').uncheck());
    assert.ok(sameChecksum(back.checksum, original.checksum));
  });

  it('a curve trimline τ(v) re-solves; one outside the t_range is a named error inline and the surfaces stay', async () => {
    const original = await open('ref-sphere-fillet');
    const curve = await choose('fillet.u1', 'at', 'curve t = τ(v)');
    const tau = control('fillet.u1', 'tau');
    assert.equal(await tau.locator('input').inputValue(), 'th0', 'the curve starts as the iso-line it replaces');
    assert.equal(await shownOption('fillet.u1', 'replaces'), 't0');
    assert.ok(sameChecksum(curve.checksum, original.checksum), 'τ = th0 is the iso-line t0');

    const wavy = await change(() => tau.locator('input').fill(TAU_INSIDE));
    assert.equal(wavy.lastError, null);
    assert.ok(!sameChecksum(wavy.checksum, original.checksum));
    assert.match(await derived('fillet.u1', 'x.0').inputValue(), /sin\(2\*v\)/);
    await look('fillet.u1', 'ends-curve.png');

    const outside = await change(() => tau.locator('input').fill(TAU_OUTSIDE));
    assert.match(outside.lastError, /patches\[0\]\.ends\.u1\.at: the trimline t = [\d.]+ at v = [\d.]+ is outside the t_range/);
    assert.ok(sameChecksum(outside.checksum, wavy.checksum), 'the last good surfaces were replaced');
    const inline = tau.locator('.expr-error');
    assert.ok(await inline.isVisible(), 'no message beside τ');
    assert.match(await inline.textContent(), /outside the t_range/);
    assert.ok((await page.locator('#status').textContent()).includes('outside the t_range'));
    assert.equal(await control('fillet.u1', 'detach').locator('button').isDisabled(), true, 'detach offered stale conditions');
    const img = await look('fillet.u1', 'ends-curve-error.png');
    assert.ok((await viewStats(page, img)).fraction > 0.03, 'surfaces vanished on error');

    const healed = await change(() => tau.locator('input').fill(TAU_INSIDE));
    assert.equal(healed.lastError, null);
    assert.ok(sameChecksum(healed.checksum, wavy.checksum));
    assert.equal(await inline.isVisible(), false, 'the message stayed after the fix');
    assert.equal(await control('fillet.u1', 'detach').locator('button').isDisabled(), false);
  });

  it('an error about an end (both ends on the plane) shows in that end\'s folder; choosing back heals', async () => {
    const original = await open('ref-sphere-fillet');
    const wrong = await choose('fillet.u1', 'surface', 'plane');
    assert.match(wrong.lastError, /patches\[0\]\.ends\.u1/);
    assert.ok(sameChecksum(wrong.checksum, original.checksum), 'the last good surfaces were replaced');
    const message = end('fillet.u1').locator('.end-error');
    assert.ok(await message.isVisible(), 'no message in the end\'s folder');
    assert.equal(await message.textContent(), wrong.lastError.replace(/^\w+: /, ''));
    assert.equal(await end('fillet.u0').locator('.end-error').isVisible(), false);
    await look('fillet.u1', 'ends-end-error.png');
    const healed = await choose('fillet.u1', 'surface', 'sphere');
    assert.equal(healed.lastError, null);
    assert.ok(sameChecksum(healed.checksum, original.checksum));
    assert.equal(await message.isVisible(), false);
  });

  it('editing the sphere\'s x re-derives the blend', async () => {
    const original = await open('ref-sphere-fillet');
    const before = await derived('fillet.u1', 'x.0').inputValue();
    const wider = await change(() => page.locator('#panel [data-expr="patches[2].x"] input').fill('1.3*rho*sin(t)*cos(v)'));
    assert.equal(wider.lastError, null);
    assert.ok(!sameChecksum(wider.checksum, original.checksum));
    const after = await derived('fillet.u1', 'x.0').inputValue();
    assert.notEqual(after, before);
    assert.match(after, /^1\.0183\d*\*cos\(v\)$/, '1.3 sin(0.9) cos(v)');
    await look('fillet.u1', 'ends-surface-edit.png');
  });

  it('detach types the derived texts (same surface); attach gives the end back by reference', async () => {
    const original = await open('ref-sphere-fillet');
    const texts = await derivedTexts('fillet.u1');
    const detached = await change(() => control('fillet.u1', 'detach').locator('button').click());
    assert.equal(detached.lastError, null);
    assert.ok(sameChecksum(detached.checksum, original.checksum), 'the detached conditions give another surface');
    for (const axis of ['x', 'y', 'z']) {
      for (let k = 0; k < texts[axis].length; k++) {
        const typed = page.locator(`#panel [data-expr="patches[0].boundary.${axis}.u1[${k}]"] input`);
        assert.equal(await typed.inputValue(), texts[axis][k], `${axis}.u1[${k}]`);
      }
    }
    assert.equal(await page.locator('#panel [data-functions="fillet"] [data-end-note]').count(), 1, 'u0 is still by reference');
    assert.equal(await end('fillet.u1').locator('[data-derived]').count(), 0);
    assert.equal(await control('fillet.u1', 'attach').count(), 1);
    assert.match(await control('fillet.u0', 'detach').getAttribute('title'), /current values/);
    await look('fillet.u1', 'ends-detached.png');

    // A typed condition is now an ordinary field: editing it changes the blend.
    const edited = await change(() => page.locator('#panel [data-expr="patches[0].boundary.z.u1[1]"] input').fill('0.5'));
    assert.equal(edited.lastError, null);
    assert.ok(!sameChecksum(edited.checksum, original.checksum));

    // Attach: the sphere (the surface u0 does not meet) at t0, tangency, power 1 = p1.
    const attached = await change(() => control('fillet.u1', 'attach').locator('button').click());
    assert.equal(attached.lastError, null);
    assert.equal(await shownOption('fillet.u1', 'surface'), 'sphere');
    assert.equal(await control('fillet.u1', 'power').locator('input').inputValue(), '1');
    assert.ok(sameChecksum(attached.checksum, original.checksum), 'attached back, the fillet is not the original');
    assert.deepEqual(await derivedTexts('fillet.u1'), texts);
    assert.equal(await page.locator('#panel [data-expr^="patches[0].boundary"]').count(), 0);
    await look('fillet.u1', 'ends-attached.png');
  });

  it('one undo takes a detach back, one redo does it again; a continuity change is one step too', async () => {
    const original = await open('ref-sphere-fillet');
    const history = () => page.evaluate(() => window.__pdesurf.history());
    const stepped = async (depth) => page.waitForFunction((d) => window.__pdesurf.history().depth > d, depth, { timeout: 5000 });
    const texts = await derivedTexts('fillet.u1');
    let { depth } = await history();
    await change(() => control('fillet.u1', 'detach').locator('button').click());
    await stepped(depth);
    ({ depth } = await history());
    assert.equal(await page.locator('#panel [data-expr^="patches[0].boundary"]').count(), 6);

    const undone = await change(() => page.locator('#toolbar [data-action="undo"]').click());
    assert.equal(undone.lastError, null);
    assert.ok(sameChecksum(undone.checksum, original.checksum));
    assert.equal(await page.locator('#panel [data-expr^="patches[0].boundary"]').count(), 0, 'the typed fields stayed');
    assert.equal(await page.locator('#panel [data-functions="fillet"] [data-end-note]').count(), 2);
    assert.deepEqual(await derivedTexts('fillet.u1'), texts);
    assert.equal(await shownOption('fillet.u1', 'surface'), 'sphere');
    assert.equal((await history()).depth, depth - 1, 'the detach was more than one step');
    await look('fillet.u1', 'ends-undo-detach.png');

    await change(() => page.locator('#toolbar [data-action="redo"]').click());
    assert.equal(await page.locator('#panel [data-expr^="patches[0].boundary"]').count(), 6);
    assert.equal(await control('fillet.u1', 'attach').count(), 1);
    await change(() => page.locator('#toolbar [data-action="undo"]').click());

    // A continuity change (which also raises the orders) is one step.
    ({ depth } = await history());
    await choose('fillet.u0', 'continuity', 'curvature (G2)');
    await stepped(depth);
    assert.equal((await history()).depth, depth + 1);
    const back = await change(() => page.locator('#toolbar [data-action="undo"]').click());
    assert.ok(sameChecksum(back.checksum, original.checksum));
    assert.equal(await shownOption('fillet.u0', 'continuity'), 'tangency (G1)');
    assert.equal(await end('fillet.u0').locator('[data-derived]').count(), 6);
  });

  it('detaching both ends leaves a typed blend with explicit orders', async () => {
    const original = await open('ref-sphere-fillet');
    await change(() => control('fillet.u0', 'detach').locator('button').click());
    const both = await change(() => control('fillet.u1', 'detach').locator('button').click());
    assert.equal(both.lastError, null);
    assert.ok(sameChecksum(both.checksum, original.checksum));
    assert.equal(await page.locator('#panel [data-functions="fillet"] [data-expr]').count(), 15);
  });

  it('a curvature end detached beside a tangency end keeps order 6 and the surface', async () => {
    await open('ref-sphere-fillet');
    const g2 = await choose('fillet.u1', 'continuity', 'curvature (G2)');
    const detached = await change(() => control('fillet.u1', 'detach').locator('button').click());
    assert.equal(detached.lastError, null, 'the detached scene does not load');
    assert.ok(sameChecksum(detached.checksum, g2.checksum));
    const order = page.locator('#panel [data-patch="fillet"] [data-order="x"] select');
    assert.equal(await order.evaluate((s) => s.options[s.selectedIndex].textContent), '6');
  });

  it('a derived text over the expression limit is not detached: the end stays by reference and says why', async () => {
    const scene = JSON.parse(fs.readFileSync(path.join(ROOT, 'examples', 'ref-sphere-fillet.json'), 'utf8'));
    const sphere = scene.patches.find((p) => p.name === 'sphere');
    sphere.x += ' + ' + Array.from({ length: 24 }, (_, k) => `0.0001*cos(${k + 2}*v)*sin(t)`).join(' + ');
    scene.patches[0].ends.u1.at = { t: 'th0 + 0.1 + 0.05*sin(v)', replaces: 't0' }; // tau in every t: x(1) > 1000 characters
    const long = await h.open(`/web/#${await encodeState({ scene })}`);
    await waitReady(long);
    const before = await long.evaluate(() => window.__pdesurf.solveCount);
    await long.locator('#panel [data-end="fillet.u1"] [data-end-field="detach"] button').click();
    const message = long.locator('#panel [data-end="fillet.u1"] .end-error');
    assert.match(await message.textContent(), /^cannot detach: the derived x\S* has \d+ characters, more than an expression may have \(1000\); the end stays by reference$/);
    assert.ok(await message.isVisible());
    assert.equal(await long.locator('#panel [data-end="fillet.u1"] [data-end-field="surface"]').count(), 1, 'the reference went');
    assert.equal(await long.evaluate(() => window.__pdesurf.solveCount), before, 'a refused detach re-solved');
    await long.close();
  });

  it('the offset cylinders: G2 ends of order 6, their powers and continuity', async () => {
    const original = await open('ref-offset-cylinders-g2');
    assert.equal(await shownOption('transition.u0', 'continuity'), 'curvature (G2)');
    assert.equal(await control('transition.u0', 'power').locator('input').inputValue(), 'p0');
    assert.equal(await end('transition.u0').locator('[data-derived]').count(), 9);
    assert.equal(await derived('transition.u1', 'x.0').inputValue(), '0.5 + 0.6*cos(v)');
    await look('transition.u0', 'ends-cylinders.png');

    await change(() => control('transition.u0', 'power-number').click());
    const fuller = await change(() => control('transition.u0', 'power').locator('input').fill('1.8'));
    assert.equal(fuller.lastError, null);
    assert.ok(!sameChecksum(fuller.checksum, original.checksum));
    // Tangency at u0 keeps order 6 (allowed above what it needs): X_uu is the ruled surface's
    // 0, which is also the cylinder's own (its rulings are straight, S_tt = 0): same blend.
    const g1 = await choose('transition.u0', 'continuity', 'tangency (G1)');
    assert.equal(g1.lastError, null);
    assert.ok(sameChecksum(g1.checksum, fuller.checksum));
    assert.equal(await end('transition.u0').locator('[data-derived]').count(), 9);
    assert.equal(await derived('transition.u0', 'z.2').inputValue(), '0');
    await look('transition.u0', 'ends-cylinders-g1.png');
  });

  it('a version-2 blend\'s typed end can be attached to the surface that meets it', async () => {
    await open('you2004-fig2a');
    const folder = page.locator('#panel [data-ends="blend"]');
    assert.equal(await folder.evaluate((el) => el.classList.contains('closed')), true, 'nothing by reference: folded');
    await folder.locator(':scope > .title').click();
    assert.equal(await page.locator('#panel [data-functions="blend"] [data-expr]').count(), 15);
    const attached = await change(() => control('blend.u1', 'attach').locator('button').click());
    assert.equal(attached.lastError, null);
    assert.equal(await shownOption('blend.u1', 'surface'), 'cone', 'the cone meets u1');
    assert.equal(await page.locator('#panel [data-functions="blend"] [data-expr]').count(), 9, 'u1\'s typed fields stayed');
    assert.equal(await derived('blend.u1', 'z.0').inputValue(), '2');
    await look('blend.u1', 'ends-attach-v2.png');
  });

  it('shows a surface\'s name as text, never as markup', async () => {
    const scene = JSON.parse(fs.readFileSync(path.join(ROOT, 'examples', 'ref-sphere-fillet.json'), 'utf8'));
    const name = '<img src=x onerror="window.__pwned=1">&amp;';
    scene.patches[2].name = name;
    scene.patches[0].ends.u1.surface = name;
    const hostile = await h.open(`/web/#${await encodeState({ scene })}`);
    assert.equal(await hostile.evaluate(() => window.__pdesurf.lastError), null);
    const select = hostile.locator('#panel [data-end="fillet.u1"] [data-end-field="surface"] select');
    assert.equal(await select.evaluate((s) => s.options[s.selectedIndex].textContent), name);
    assert.equal(await hostile.locator('#panel [data-end="fillet.u1"] [data-end-field="surface"] .display').textContent(), name);
    assert.equal(await hostile.locator('#panel img').count(), 0);
    assert.equal(await hostile.evaluate(() => window.__pwned), undefined);
    await hostile.close();
  });

  it('on a phone (390×844) the Controls sheet reaches the Ends folder', async () => {
    const phone = await h.open('/web/#example=ref-sphere-fillet', { viewport: { width: 390, height: 844 } });
    await phone.locator('[data-action="panel"]').click();
    const select = phone.locator('#panel [data-end="fillet.u1"] [data-end-field="continuity"] select');
    await select.scrollIntoViewIfNeeded();
    const box = await select.boundingBox();
    assert.ok(box && box.y >= 0 && box.y + box.height <= 844 && box.x >= 0 && box.x + box.width <= 390, JSON.stringify(box));
    const before = await phone.evaluate(() => window.__pdesurf.solveCount);
    await select.selectOption('curvature (G2)');
    await phone.waitForFunction((n) => window.__pdesurf.solveCount > n, before);
    assert.equal(await phone.evaluate(() => window.__pdesurf.lastError), null);
    await phone.locator('#panel [data-end="fillet.u1"]').scrollIntoViewIfNeeded();
    await shoot(phone, 'ends-phone.png');
    // The edit's link is written (its deflater loads on first use): closing before would
    // abort that request.
    await phone.waitForFunction(() => location.hash.startsWith('#s='), null, { timeout: 10_000 });
    await phone.close();
  });

  it('logged no console error, page error or failed request', () => {
    assert.deepEqual(h.problems, []);
  });
});
