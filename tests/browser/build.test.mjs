// Building a model from nothing in the page (web/features/build.js): a new empty scene, surfaces
// from the library, placed, blended by picking two borders in the view (1280×800) or by the
// panel's choices only (390×844), undone back to empty and redone; the link decodes in the
// CLI to that scene and `pdesurf check` passes; a sphere filleted into a plane follows a
// moved sphere and stays G1; a hole filled by picking four borders; deleting a surface a
// blend names, both answers; bad names and picks are named and change nothing. The gizmo
// drag's frame timings: drag-frames.test.mjs.
// Screenshots: build/browser/build-*.png.
//   PDESURF_WASM_DIR=build/wasm PDESURF_CLI=build/native/pdesurf node --test tests/browser/build.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { skip, startHarness, hooks, shoot, REPO } from './harness.mjs';
import { CLI, clickBorder, solving, checkLink } from './build-tools.mjs';
import { encodeState } from '../../web/link/link-codec.js';

const scene = (page) => page.evaluate(() => JSON.parse(window.__pdesurf.sceneText()));
const names = async (page) => (await scene(page)).patches.map((p) => p.name);
const history = (page) => page.evaluate(() => window.__pdesurf.history());

const control = (page, key) => page.locator(`#panel [data-build="${key}"]`);
const button = (page, name) => page.locator('#panel .build-folder button', { hasText: name }).first();

async function addSurface(page, label) {
  await control(page, 'kind').locator('select').selectOption({ label });
  return solving(page, () => button(page, 'add surface').click());
}

// Close a page once its last edit's link is written (the deflater loads on first use; closing
// before would abort that request). A page whose edits were all refused writes none.
async function settle(page) {
  await page.waitForFunction(() => location.hash.startsWith('#s='), null, { timeout: 3000 }).catch(() => {});
  await page.waitForTimeout(300);
  await page.close();
}

async function waitLink(page) {
  await page.waitForFunction(() => location.hash.startsWith('#s='), null, { timeout: 10_000 });
  await page.waitForTimeout(400); // the hash sync settles
  return page.evaluate(() => location.href);
}

// Four strips around the hole [-1, 1]²: one rectangle x in [1, 2] turned by 0, 90, 180, 270°
// about z, so their t0 borders (x = 1 before turning) close into a square loop; all four are
// pieces of one paraboloid z = c(x² + y²) (turning keeps it), so a G1 fill exists.
function fourStrips() {
  const strip = (k) => ({ name: `strip${k}`, kind: 'surface', t_range: [1, 2], v_range: [-1, 1],
    x: 't', y: 'v', z: 'c*(t^2 + v^2)', ...(k ? { placement: { rotate: [0, 0, 90 * k] } } : {}) });
  return { format: 'pdesurf-scene', version: 4, title: 'four strips',
    parameters: { c: { value: 0.1, min: 0, max: 0.3 } }, patches: [0, 1, 2, 3].map(strip) };
}

describe('building a model in the page', { skip }, () => {
  let h;
  before(async () => {
    assert.ok(fs.existsSync(CLI), `no CLI at ${CLI}`);
    h = await startHarness();
  });
  after(async () => {
    await h?.close();
  });

  it('1280×800: from an empty scene, a plane and a cylinder, placed, blended G2 by picking; the link checks in the CLI', async () => {
    const page = await h.open('/web/#example=ref-sphere-fillet');
    await solving(page, () => button(page, 'new empty scene').click());
    assert.deepEqual(await names(page), []);
    assert.equal((await hooks(page)).lastError, null);
    await addSurface(page, 'plane disc / annulus');
    const one = (await hooks(page)).solveCount;
    await addSurface(page, 'cylinder');
    await page.waitForTimeout(300);
    assert.equal((await hooks(page)).solveCount, one + 1, 'adding a surface draws within one solve');
    assert.deepEqual(await names(page), ['annulus1', 'cylinder1']);
    // Placed by numbers in its folder: up by 0.5.
    await page.locator('#panel [data-patch="cylinder1"] [data-action="select"]').click(); // selected already: stays
    const z = page.locator('#panel [data-placement="z"] input');
    await solving(page, async () => {
      await z.fill('0.5');
      await z.press('Enter');
    });
    assert.deepEqual((await scene(page)).patches[1].placement.translate, [0, 0, 0.5]);
    // Curvature continuity, then two borders picked in the view.
    await control(page, 'blend-continuity').locator('select').selectOption({ label: 'curvature (G2)' });
    await control(page, 'blend-pick').locator('input').check();
    await clickBorder(page, 'annulus1', 't0');
    const before = await hooks(page);
    await page.waitForTimeout(200);
    assert.equal((await hooks(page)).solveCount, before.solveCount, 'one pick does not solve');
    const picked = await solving(page, () => clickBorder(page, 'cylinder1', 't0'));
    await page.waitForTimeout(300);
    assert.equal((await hooks(page)).solveCount, picked.solveCount, 'a picked blend draws within one solve');
    const built = await scene(page);
    assert.deepEqual(built.patches.map((p) => p.name), ['annulus1', 'cylinder1', 'blend1']);
    assert.deepEqual(built.patches[2].ends.u0, { surface: 'annulus1', at: 't0', continuity: 'curvature', power: 1 });
    assert.equal((await hooks(page)).lastError, null);
    // The blend meets both surfaces' borders: a copy would meet them too, so it offers none.
    const copyBlend = page.locator('#panel [data-patch="blend1"] [data-action="duplicate"]');
    assert.ok(await copyBlend.isDisabled());
    assert.match(await copyBlend.getAttribute('title'), /^blend1 meets annulus1, cylinder1: a copy would meet the same edges/);
    assert.ok(await page.locator('#panel [data-patch="cylinder1"] [data-action="duplicate"]').isEnabled());
    await shoot(page, 'build-picked-1280.png');
    const { scene: linked, report } = checkLink(await waitLink(page));
    assert.deepEqual(linked.patches.map((p) => p.name), ['annulus1', 'cylinder1', 'blend1']);
    assert.equal(report.ok, true);
    const levels = report.joins.map((j) => j.promised ?? j.level);
    assert.equal(report.joins.length, 2, JSON.stringify(report.joins));
    assert.ok(report.joins.every((j) => j.ok), JSON.stringify(report.joins));
    assert.ok(levels.every((l) => l === 'G2' || l === 2), JSON.stringify(levels));
    await settle(page);
  });

  it('390×844: the same through the panel only, then undo back to empty and redo', async () => {
    const page = await h.open('/web/#example=ref-sphere-fillet', { viewport: { width: 390, height: 844 } });
    await page.locator('#toolbar [data-action="panel"]').click();
    await solving(page, () => button(page, 'new empty scene').click());
    const base = (await history(page)).depth;
    await addSurface(page, 'plane disc / annulus');
    await addSurface(page, 'cylinder');
    const z = page.locator('#panel [data-placement="z"] input'); // cylinder1 is selected: its placement
    await solving(page, async () => {
      await z.fill('0.5');
      await z.press('Enter');
    });
    await control(page, 'blend-continuity').locator('select').selectOption({ label: 'curvature (G2)' });
    await control(page, 'blend-a').locator('select').selectOption({ label: 'annulus1 · t0' });
    await control(page, 'blend-b').locator('select').selectOption({ label: 'cylinder1 · t0' });
    await solving(page, () => button(page, 'make the blend').click());
    assert.deepEqual(await names(page), ['annulus1', 'cylinder1', 'blend1']);
    const addButton = await button(page, 'add surface').boundingBox();
    assert.ok(addButton.height >= 32, `touch target ${addButton.height} px`);
    await page.locator('#panel .outliner').scrollIntoViewIfNeeded();
    await shoot(page, 'build-panel-390.png');
    await page.waitForTimeout(500); // the last step rests
    assert.equal((await history(page)).depth, base + 4, 'one undo step per edit');
    const built = await scene(page);
    assert.equal(built.patches[2].ends.u1.continuity, 'curvature');
    assert.ok(checkLink(await waitLink(page)).report.ok);
    await solving(page, () => page.locator('#toolbar [data-action="undo"]').click());
    assert.deepEqual((await scene(page)).patches[1].placement.translate, [0, 0, 0.5]);
    for (const expected of [['annulus1', 'cylinder1'], ['annulus1'], []]) {
      await solving(page, () => page.locator('#toolbar [data-action="undo"]').click());
      assert.deepEqual(await names(page), expected);
    }
    for (const expected of [['annulus1'], ['annulus1', 'cylinder1'], ['annulus1', 'cylinder1'], ['annulus1', 'cylinder1', 'blend1']]) {
      await solving(page, () => page.locator('#toolbar [data-action="redo"]').click());
      assert.deepEqual(await names(page), expected);
    }
    await settle(page);
  });

  it('a sphere filleted into a plane follows the moved sphere and stays G1', async () => {
    const page = await h.open('/web/#example=ref-sphere-fillet');
    // Selected by a click on it in the view (the top of the sphere: nothing in front of it).
    const top = await page.evaluate(() => {
      const { nu, nv } = window.__pdesurf.lastSolve;
      return window.__pdesurf.vertexScreen('sphere', Math.round(nv / 4) * (nu + 1) + nu - 2);
    });
    await page.mouse.click(top.x, top.y);
    assert.equal((await page.evaluate(() => window.__pdesurf.build())).selection, 'sphere');
    assert.equal(await page.locator('#panel .outliner li.selected').getAttribute('data-patch'), 'sphere');
    for (const [key, value] of [['x', '0.3'], ['rx', '10']]) {
      const input = page.locator(`#panel [data-placement="${key}"] input`).first();
      await solving(page, async () => {
        await input.fill(value);
        await input.press('Enter');
      });
    }
    const s = await scene(page);
    assert.equal(s.version, 4);
    assert.deepEqual(s.patches[2].placement, { translate: [0.3, 0, 0], rotate: [10, 0, 0], scale: 1 });
    const joins = await page.evaluate(() => window.__pdesurf.analysis().report.joins);
    assert.ok(joins.length === 2 && joins.every((j) => j.ok), JSON.stringify(joins));
    // The certificate as the joins panel shows it.
    const folder = page.locator('#panel [data-folder="joins"]');
    await folder.locator('.title').first().click();
    assert.match(await folder.locator('.joins-summary').textContent(), /^2 joins/);
    assert.equal(await folder.locator('.joins-figure.bad').count(), 0);
    await shoot(page, 'build-moved-sphere-1280.png');
    await settle(page);
  });

  it('deleting a surface a blend names asks, and both answers work; undo restores', async () => {
    const page = await h.open('/web/#example=ref-sphere-fillet');
    const del = page.locator('#panel [data-patch="sphere"] [data-action="delete"]');
    await del.click();
    await page.locator('#panel .outliner-ask').waitFor();
    await solving(page, () => page.locator('#panel [data-action="delete-dependents"]').click());
    assert.deepEqual(await names(page), ['plane']);
    await solving(page, () => page.locator('#toolbar [data-action="undo"]').click());
    assert.deepEqual(await names(page), ['fillet', 'plane', 'sphere']);
    await del.click();
    await solving(page, () => page.locator('#panel [data-action="detach-dependents"]').click());
    const s = await scene(page);
    assert.deepEqual(s.patches.map((p) => p.name), ['fillet', 'plane']);
    assert.equal(s.patches[0].ends.u1, undefined);
    assert.ok(s.patches[0].boundary, 'the detached end is typed');
    assert.equal((await hooks(page)).lastError, null);
    await settle(page);
  });

  it('bad input: markup names stay text, duplicates are refused by name, a same-border pick adds nothing', async () => {
    const page = await h.open('/web/#example=ref-sphere-fillet');
    const name = page.locator('#panel [data-patch="plane"] input[type="text"]');
    const bold = await page.locator('#panel b').count();
    await solving(page, async () => {
      await name.fill('<b>flat</b>');
      await name.press('Enter');
    });
    assert.deepEqual(await names(page), ['fillet', '<b>flat</b>', 'sphere']);
    assert.equal(await page.locator('#panel b').count(), bold, 'a name never becomes markup');
    await control(page, 'blend-a').locator('select').selectOption({ label: '<b>flat</b> · t0' });
    const renamed = page.locator('#panel [data-patch="<b>flat</b>"] input[type="text"]');
    await renamed.fill('sphere');
    await renamed.press('Enter');
    await page.waitForTimeout(200);
    assert.match(await page.locator('#panel .build-message').textContent(), /sphere/);
    assert.deepEqual(await names(page), ['fillet', '<b>flat</b>', 'sphere']);
    await control(page, 'blend-a').locator('select').selectOption({ label: 'sphere · t1' });
    await control(page, 'blend-b').locator('select').selectOption({ label: 'sphere · t1' });
    await button(page, 'make the blend').click();
    await page.waitForTimeout(200);
    assert.match(await page.locator('#panel .build-message').textContent(), /^cannot blend: /);
    assert.deepEqual(await names(page), ['fillet', '<b>flat</b>', 'sphere']);
    // A custom surface whose expression does not parse names the field and adds nothing.
    await page.locator('#panel .build-folder .title', { hasText: 'Custom surface' }).click();
    const x = control(page, 'custom-x').locator('input');
    await x.fill('cos(v');
    await x.press('Enter');
    await page.locator('#panel .build-folder button', { hasText: 'add custom surface' }).click();
    await page.waitForTimeout(200);
    assert.match(await page.locator('#panel .build-message').textContent(), /^cannot add a custom surface: .*x.*\)/);
    assert.deepEqual(await names(page), ['fillet', '<b>flat</b>', 'sphere']);
    await settle(page);
  });

  it('a link whose placement flattens a surface is refused by name; the default example opens', async () => {
    const s = JSON.parse(fs.readFileSync(path.join(REPO, 'examples', 'ref-sphere-fillet.json'), 'utf8'));
    s.version = 4;
    s.patches[2].placement = { scale: 0 };
    const page = await h.open(`/web/#${await encodeState({ scene: s })}`);
    const state = await hooks(page);
    assert.match(state.notice, /^cannot open the link: .*patches\[2\]\.placement\.scale: a scale of 0 flattens the surface/);
    await settle(page);
  });

  it('a blend to a border where dS/dt vanishes shows the core\'s error beside the pick and adds nothing', async () => {
    const surfaces = [
      { name: 'a', kind: 'surface', t_range: [2, 3], v_range: [0, '2*pi'], x: 't*cos(v)', y: 't*sin(v)', z: '0' },
      { name: 'c', kind: 'surface', t_range: [0, 1], v_range: [0, '2*pi'], x: 'cos(v)', y: 'sin(v)', z: '1 + t^2' },
    ];
    const page = await h.open(`/web/#${await encodeState({ scene: { format: 'pdesurf-scene', version: 4, patches: surfaces } })}`);
    const depth = (await history(page)).depth;
    await control(page, 'blend-a').locator('select').selectOption({ label: 'a · t0' });
    await control(page, 'blend-b').locator('select').selectOption({ label: 'c · t0' });
    await solving(page, () => button(page, 'make the blend').click());
    await page.waitForFunction(() => /vanishes/.test(document.querySelector('#panel .build-message').textContent));
    assert.match(await page.locator('#panel .build-message').textContent(),
      /^cannot blend: InvalidField: patches\[2\]\.ends\.u1\.at: dS\/dt of 'c' vanishes on the trimline/);
    await page.waitForFunction(() => window.__pdesurf.lastError === null, null, { timeout: 10_000 }); // the scene as it was solves again
    assert.deepEqual(await names(page), ['a', 'c']);
    await page.waitForTimeout(500);
    assert.equal((await history(page)).depth, depth, 'a refused blend is no undo step');
    await shoot(page, 'build-refused-1280.png');
    await settle(page);
  });

  it('a hole filled by picking four borders; deleting a strip the fill names, both answers', async () => {
    const page = await h.open(`/web/#${await encodeState({ scene: fourStrips() })}`);
    assert.equal((await hooks(page)).lastError, null);
    await page.locator('#panel .build-folder .title', { hasText: 'Fill a loop' }).click(); // closed at first
    await control(page, 'fill-pick').locator('input').check();
    for (const k of [0, 2, 1]) await clickBorder(page, `strip${k}`, 't0');
    await solving(page, () => clickBorder(page, 'strip3', 't0'));
    assert.equal((await hooks(page)).lastError, null);
    const s = await scene(page);
    const fill = s.patches.find((p) => p.kind === 'bezier');
    assert.equal(fill.name, 'fill1');
    assert.deepEqual(Object.keys(fill.borders).sort(), ['u0', 'u1', 'v0', 'v1']);
    assert.equal(fill.normals, undefined, 'a fill by its borders needs no guiding normals');
    const joins = await page.evaluate(() => window.__pdesurf.analysis().report.joins);
    assert.equal(joins.filter((j) => j.patch === 'fill1').length, 4, JSON.stringify(joins));
    assert.ok(joins.every((j) => j.ok && j.level === 'G1'), JSON.stringify(joins));
    await shoot(page, 'build-fill-1280.png');
    const { report } = checkLink(await waitLink(page));
    assert.equal(report.ok, true);

    const del = page.locator('#panel [data-patch="strip1"] [data-action="delete"]');
    await del.click();
    await solving(page, () => page.locator('#panel [data-action="delete-dependents"]').click());
    assert.deepEqual(await names(page), ['strip0', 'strip2', 'strip3']);
    await solving(page, () => page.locator('#toolbar [data-action="undo"]').click());
    assert.deepEqual(await names(page), ['strip0', 'strip1', 'strip2', 'strip3', 'fill1']);
    await del.click();
    await solving(page, () => page.locator('#panel [data-action="detach-dependents"]').click());
    const detached = await scene(page);
    assert.deepEqual(detached.patches.map((p) => p.name), ['strip0', 'strip2', 'strip3', 'fill1']);
    assert.equal(Object.keys(detached.patches[3].borders || {}).length, 3, 'the deleted strip\'s border became typed rings');
    assert.equal((await hooks(page)).lastError, null);
    await settle(page);
  });

  it('a curve trimline shaped by five values becomes a trigonometric τ(v) and stays G1', async () => {
    const page = await h.open('/web/#example=ref-sphere-fillet');
    const end = page.locator('#panel [data-end="fillet.u1"]');
    await solving(page, () => end.locator('[data-end-field="at"] select').selectOption({ label: 'curve t = τ(v)' }));
    const values = end.locator('[data-end-field="tau-values"]');
    await values.locator('.title').click();
    const input = (k) => values.locator('.controller.number input').nth(k);
    const type = async (k, text) => {
      await input(k).fill(text);
      await input(k).press('Enter');
    };
    // One value raised off the border: the curve through them dips below t0 between them.
    const before = await hooks(page);
    await type(0, '1.2');
    await page.waitForTimeout(300);
    assert.match(await values.locator('.tau-values-note').textContent(), /^the curve through these values reaches t = 0\.\d+ at v = [\d.]+, outside \[0\.9000, 3\.092\]/);
    assert.equal((await hooks(page)).solveCount, before.solveCount, 'a curve outside the range is not sent');
    for (const k of [1, 2, 3]) await type(k, '1.2');
    await solving(page, () => type(4, '1.2'));
    await solving(page, () => type(0, '1.3'));
    assert.equal((await hooks(page)).lastError, null);
    assert.equal(await values.locator('.tau-values-note').textContent(), '');
    const tau = (await scene(page)).patches[0].ends.u1.at.t;
    assert.match(tau, /cos\(|sin\(/, tau);
    assert.equal(await end.locator('[data-end-field="tau"] input').inputValue(), tau);
    const joins = await page.evaluate(() => window.__pdesurf.analysis().report.joins);
    assert.ok(joins.length === 2 && joins.every((j) => j.ok), JSON.stringify(joins));
    await values.scrollIntoViewIfNeeded();
    await shoot(page, 'build-tau-values-1280.png');
    await settle(page);
  });

  it('left no console or page errors', () => {
    assert.deepEqual(h.problems, []);
  });
});
