// The page at four screen sizes: the 3D view gets the space (≥ 60 % of a phone's screen
// is canvas the user can touch), and every control can be reached — on compact screens
// through the toolbar's Examples and Controls buttons (web/ui/layout.js) — without
// anything covering it. Screenshots of each size and each drawer: build/browser/layout-*.png.
//   node --test tests/browser/layout.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { skip, startHarness, shoot, viewStats, exampleIndex } from './harness.mjs';

const SIZES = [
  { name: 'phone', width: 390, height: 844, compact: true, minCanvas: 0.6 },
  { name: 'tablet', width: 768, height: 1024, compact: true, minCanvas: 0.6 },
  { name: 'laptop', width: 1280, height: 800, compact: false, minCanvas: 0.4 },
  { name: 'desktop', width: 1920, height: 1080, compact: false, minCanvas: 0.5 },
];

// Share of a 24×24 grid of points over the window where the canvas itself is hit.
const canvasShare = (page) => page.evaluate(() => {
  const canvas = document.querySelector('#viewport canvas');
  let hits = 0;
  const n = 24;
  for (let i = 0; i < n; i++) {
    for (let j = 0; j < n; j++) {
      if (document.elementFromPoint(((i + 0.5) / n) * innerWidth, ((j + 0.5) / n) * innerHeight) === canvas) hits++;
    }
  }
  return hits / (n * n);
});

// Whether the element matched by `selector` (k-th) can be scrolled to and is on top at its centre.
const reachable = (page, selector, k) => page.evaluate(([sel, i]) => {
  const el = document.querySelectorAll(sel)[i];
  if (el.getClientRects().length === 0) return 'hidden'; // e.g. the settings of another shading mode
  el.scrollIntoView({ block: 'center', inline: 'nearest' });
  const r = el.getBoundingClientRect();
  if (r.width < 1 || r.height < 1) return `${sel}[${i}] has no size`;
  const x = r.left + r.width / 2;
  const y = r.top + r.height / 2;
  if (x < 0 || y < 0 || x > innerWidth || y > innerHeight) return `${sel}[${i}] is off screen at ${x},${y}`;
  const top = document.elementFromPoint(x, y);
  return top === el || el.contains(top) ? null : `${sel}[${i}] is covered by ${top?.tagName}#${top?.id}.${top?.className}`;
}, [selector, k]);

// Every folder of the panel opened, so that every control is there to be reached.
async function openAllFolders(page) {
  const left = await page.evaluate(() => {
    for (let round = 0; round < 200; round++) {
      // lil-gui sets aria-expanded at once and the class "closed" a frame later.
      const title = [...document.querySelectorAll('#panel .lil-gui > .title[aria-expanded="false"]')].find((t) => t.getClientRects().length > 0);
      if (!title) return 0;
      title.click();
    }
    return -1;
  });
  assert.equal(left, 0, 'folders that do not stay open');
  await settled(page);
}

// No CSS transition or animation running (lil-gui's folders, the drawers): hit tests see the end state.
// lil-gui starts a folder's transition a frame after the click: let two frames pass first.
async function settled(page) {
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(() => r()))));
  await page.waitForFunction(() => document.getAnimations().every((a) => a.playState !== 'running'), null, { timeout: 10_000 });
}

// The panel's controls: each controller's widget (input, button, select, slider).
const WIDGETS = '#panel .controller:not(.disabled) :is(input, button, select, .slider)';

describe('layout at every screen size', { skip }, () => {
  let h;
  before(async () => {
    h = await startHarness();
  });
  after(async () => {
    await h?.close();
  });

  for (const size of SIZES) {
    it(`${size.name} ${size.width}×${size.height}: the view gets the space and every control is reachable`, async () => {
      const page = await h.open('/web/#example=you2004-fig2a', { viewport: { width: size.width, height: size.height } });
      const share = await canvasShare(page);
      assert.ok(share >= size.minCanvas, `the canvas covers ${(100 * share).toFixed(0)} % of the window`);
      const img = await shoot(page, `layout-${size.name}.png`);
      assert.ok((await viewStats(page, img)).fraction > 0.02, 'no surface drawn');
      // The toolbar and the title do not overlap.
      const [bar, title] = await page.evaluate(() => ['#toolbar', '#title-bar'].map((s) => document.querySelector(s).getBoundingClientRect().toJSON()));
      const overlap = bar.left < title.right && title.left < bar.right && bar.top < title.bottom && title.top < bar.bottom;
      assert.ok(!overlap, `toolbar ${JSON.stringify(bar)} overlaps the title ${JSON.stringify(title)}`);
      const buttons = page.locator('#toolbar button');
      let shown = 0;
      for (let k = 0; k < (await buttons.count()); k++) {
        if (!(await buttons.nth(k).isVisible())) continue;
        shown++;
        assert.equal(await reachable(page, '#toolbar button', k), null);
      }
      assert.ok(shown >= (size.compact ? 4 : 2), `${shown} toolbar buttons shown`);

      // The panel: open as a sheet on compact screens, docked otherwise.
      if (size.compact) {
        assert.equal(await page.locator('#panel').isVisible(), false, 'the panel covers the view before it is asked for');
        await page.locator('[data-action="panel"]').click();
        assert.ok(await page.locator('#panel').isVisible());
        await settled(page);
        assert.ok(await canvasShare(page) >= 0.35, 'with the panel open the view is too small');
      }
      await openAllFolders(page);
      const widgets = await page.locator(WIDGETS).count();
      assert.ok(widgets > 30, `only ${widgets} controls`);
      let reached = 0;
      for (let k = 0; k < widgets; k++) {
        const why = await reachable(page, WIDGETS, k);
        if (why === 'hidden') continue;
        assert.equal(why, null);
        reached++;
      }
      assert.ok(reached > 30, `only ${reached} controls shown`);
      await page.evaluate(() => document.querySelector('#panel').scrollTo(0, 0));
      await shoot(page, `layout-${size.name}-panel.png`);

      // The gallery: every example reachable; on compact screens it is a drawer.
      if (size.compact) {
        await page.locator('[data-action="gallery"]').click();
        assert.equal(await page.locator('#panel').isVisible(), false, 'two drawers open at once');
        // Done sliding in.
        await page.waitForFunction(() => getComputedStyle(document.getElementById('gallery')).transform === 'none'
          && document.getElementById('gallery').getBoundingClientRect().left === 0);
      }
      const items = exampleIndex().length;
      assert.equal(await page.locator('#gallery [data-example]').count(), items);
      for (const k of [0, Math.floor(items / 2), items - 1]) assert.equal(await reachable(page, '#gallery [data-example]', k), null);
      await page.evaluate(() => document.querySelector('.gallery-list').scrollTo(0, 0));
      await shoot(page, `layout-${size.name}-gallery.png`);
      if (size.compact) {
        // Picking an example closes the drawer and gives the view back.
        await page.locator('#gallery [data-example="you2004-fig4a"]').click();
        await page.waitForFunction(() => window.__pdesurf.exampleId === 'you2004-fig4a');
        await page.waitForTimeout(250);
        assert.ok(await canvasShare(page) >= size.minCanvas);
        // Escape closes a drawer too.
        await page.locator('[data-action="panel"]').click();
        await page.keyboard.press('Escape');
        assert.equal(await page.locator('#panel').isVisible(), false);
      }
      await page.close();
    });
  }

  it('logged no console error, page error or failed request', () => {
    assert.deepEqual(h.problems, []);
  });
});
