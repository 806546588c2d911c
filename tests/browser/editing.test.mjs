// Editing a version-2 scene in the page: expression fields (boundary slots, force,
// primary surface) re-solve after typing; an invalid expression shows the solver's
// message beside its field and in the status line while the last good surfaces stay;
// parameters are added and removed (removing one still in use is the solver's error).
// Hooks: data-expr="<solver path>" (web/ui/expression-field.js), data-param-remove,
// data-param-new, data-param-add (web/ui/parameter-controls.js).
//   node --test tests/browser/
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { skip, startHarness, hooks, solvedAfter, shoot, viewStats, sameChecksum } from './harness.mjs';

const SLOT = 'patches[0].boundary.x.u0[1]'; // you2004-fig2a: "r0p*cos(v)"
const FORCE = 'patches[0].force.x';
const PLANE_Z = 'patches[1].z';

describe('editing expressions and parameters', { skip }, () => {
  let h, page, original;
  const field = (path) => page.locator(`#panel [data-expr="${path}"]`);
  const message = (path) => field(path).locator('.expr-error');
  // Type into a field and wait for the (debounced) solve.
  async function edit(path, text) {
    const before = await hooks(page);
    await field(path).locator('input').fill(text);
    return solvedAfter(page, before.solveCount);
  }

  before(async () => {
    h = await startHarness();
    page = await h.open('/web/#example=you2004-fig2a');
    original = await hooks(page);
    assert.equal(original.lastError, null);
  });
  after(async () => {
    await h?.close();
  });

  it('shows a field per boundary slot, force and surface coordinate with the scene\'s text', async () => {
    assert.equal(await field(SLOT).locator('input').inputValue(), 'r0p*cos(v)');
    assert.equal(await field('patches[0].boundary.z.u1[0]').locator('input').inputValue(), 'h1');
    assert.equal(await field(FORCE).locator('input').inputValue(), '0');
    assert.equal(await field(PLANE_Z).locator('input').inputValue(), '0');
    assert.equal(await page.locator('#panel [data-functions="blend"] [data-expr]').count(), 15);
    // Per surface: x, y, z and the two ends of t_range and of v_range.
    assert.equal(await page.locator('#panel [data-surface] [data-expr]').count(), 14);
    assert.equal(await field('patches[1].v_range[1]').locator('input').inputValue(), '2*pi');
  });

  it('an invalid expression shows its error inline and in the status line, and keeps the surfaces', async () => {
    const failed = await edit(SLOT, 'r0p*cso(v)');
    assert.match(failed.lastError, /unknown function 'cso'/);
    assert.ok(sameChecksum(failed.checksum, original.checksum), 'the last good surfaces were replaced');
    assert.ok(await message(SLOT).isVisible(), 'no inline message');
    const inline = await message(SLOT).textContent();
    assert.ok(inline.includes(SLOT) && inline.includes("unknown function 'cso'"), inline);
    assert.ok((await page.locator('#status').textContent()).includes(inline));
    assert.equal(await page.locator('#panel .expr-error:visible').count(), 1, 'other fields show messages');
    await field(SLOT).scrollIntoViewIfNeeded();
    const img = await shoot(page, 'expression-error.png');
    assert.ok((await viewStats(page, img)).fraction > 0.03, 'surfaces vanished on error');

    const healed = await edit(SLOT, 'r0p*cos(v)');
    assert.equal(healed.lastError, null);
    assert.ok(sameChecksum(healed.checksum, original.checksum));
    assert.equal(await message(SLOT).isVisible(), false, 'the message stayed after the fix');
  });

  it('an error without a field name lands beside the field just edited', async () => {
    const failed = await edit(PLANE_Z, 'sqrt(-1 - t)');
    assert.match(failed.lastError, /not finite/);
    assert.ok(await message(PLANE_Z).isVisible());
    const healed = await edit(PLANE_Z, '0');
    assert.equal(healed.lastError, null);
    assert.ok(sameChecksum(healed.checksum, original.checksum));
  });

  it('typing re-solves once the keys pause', async () => {
    const input = field(SLOT).locator('input');
    const before = await hooks(page);
    await input.fill('');
    await input.pressSequentially('r0p*cos(v)*1.5', { delay: 20 }); // 14 keys, 20 ms apart
    const now = await solvedAfter(page, before.solveCount);
    await page.waitForTimeout(400); // nothing else pending
    const settled = await hooks(page);
    assert.ok(settled.solveCount - before.solveCount <= 2, `${settled.solveCount - before.solveCount} solves while typing`);
    assert.equal(settled.lastError, null);
    assert.notEqual(now.checksum, original.checksum);
    assert.ok(sameChecksum((await edit(SLOT, 'r0p*cos(v)')).checksum, original.checksum));
  });

  it('a force and a primary surface can be edited; clearing the force removes it', async () => {
    const pushed = await edit(FORCE, '40*u*(1 - u)*cos(v)');
    assert.equal(pushed.lastError, null);
    assert.notEqual(pushed.checksum, original.checksum);
    await shoot(page, 'expression-force.png');
    const cleared = await edit(FORCE, '');
    assert.equal(cleared.lastError, null);
    assert.ok(sameChecksum(cleared.checksum, original.checksum));

    const tilted = await edit(PLANE_Z, '0.3*t*cos(v)');
    assert.equal(tilted.lastError, null);
    assert.notEqual(tilted.checksum, original.checksum);
    assert.ok(sameChecksum((await edit(PLANE_Z, '0')).checksum, original.checksum));
  });

  it('removing a parameter still in use gives the solver\'s error; adding it back heals', async () => {
    let before = await hooks(page);
    await page.locator('#panel [data-param-remove="r0p"]').click();
    const failed = await solvedAfter(page, before.solveCount);
    assert.match(failed.lastError, /unknown parameter 'r0p'/);
    assert.ok(sameChecksum(failed.checksum, original.checksum));
    assert.equal(await page.locator('#panel [data-param="r0p"]').count(), 0);
    assert.equal(await page.locator('#panel .expr-error:visible').count(), 1, 'the message is beside the field using it');
    await shoot(page, 'parameter-removed.png');

    before = failed;
    await page.locator('#panel [data-param-new="name"] input').fill('r0p');
    await page.locator('#panel [data-param-new="value"] input').fill('-0.5');
    await page.locator('#panel [data-param-add] button').click();
    const healed = await solvedAfter(page, before.solveCount);
    assert.equal(healed.lastError, null);
    assert.ok(sameChecksum(healed.checksum, original.checksum));
    assert.equal(await page.locator('#panel [data-param="r0p"] input').inputValue(), '-0.5');
    assert.equal(await page.locator('#panel .expr-error:visible').count(), 0);
  });

  it('a new parameter gets a slider that drives the expressions using it', async () => {
    await page.locator('#panel [data-param-new="name"] input').fill('k');
    await page.locator('#panel [data-param-new="value"] input').fill('0.3');
    let before = await hooks(page);
    await page.locator('#panel [data-param-add] button').click();
    await solvedAfter(page, before.solveCount);
    const slider = page.locator('#panel [data-param="k"]');
    assert.equal(await slider.count(), 1);
    const used = await edit('patches[0].boundary.z.u0[0]', 'k*cos(2*v)');
    assert.equal(used.lastError, null);
    assert.notEqual(used.checksum, original.checksum);
    before = used;
    await slider.locator('input').fill('0.8');
    const moved = await solvedAfter(page, before.solveCount);
    assert.equal(moved.lastError, null);
    assert.notEqual(moved.checksum, used.checksum);
    await shoot(page, 'parameter-added.png');
  });

  it('refuses a parameter name that is not a name, or taken, with a message', async () => {
    for (const [name, pattern] of [['2x', /not a name/], ['pi', /already a constant/], ['r0', /already a parameter/]]) {
      await page.locator('#panel [data-param-new="name"] input').fill(name);
      await page.locator('#panel [data-param-add] button').click();
      assert.match(await page.locator('#status').textContent(), pattern);
    }
  });

  it('logged no console error, page error or failed request', () => {
    assert.deepEqual(h.problems, []);
  });
});
