// Surface-quality analysis in the page (web/features/analysis.js), at 1280×800 and at
// phone size 390×844, on seed 000 Fig. 4a (a cylinder blended into a plane):
// normal shading, zebra stripes, mean and Gaussian curvature maps with their legend, the
// wireframe overlay and the joins folder with a highlighted join. Screenshots go to
// build/browser/analysis-<mode>-<size>.png. Needs a module with solveSceneWith
// (curvature and the join report, docs/wasm-api.md).
// Hooks: data-analysis="<setting>" (web/ui/analysis-controls.js), #curvature-legend
// [data-legend] (curvature-legend.js), [data-folder="joins"] [data-join] (joins-panel.js),
// window.__pdesurf.analysis(), patchCurvature(name), vertexScreen(name, k).
//   node --test tests/browser/
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { skip, startHarness, waitReady, shoot, BACKGROUND } from './harness.mjs';
import { blockAverage, drawnDifference } from './image-diff.mjs';

const EXAMPLE = 'you2004-fig4a';
const CYLINDER_RADIUS = 0.8; // examples/you2004-fig4a.json parameter r
const MIDDLE_GREY = [0xdc, 0xdc, 0xdc]; // three's Lut 'cooltowarm' at the middle of the range (K = 0)
const HIGHLIGHT = { fail: [0xff, 0x2d, 0x55], pick: [0xff, 0xe1, 0x4d] }; // web/viewer/join-highlight.js
const SIZES = [
  { name: 'desktop', width: 1280, height: 800 },
  { name: 'phone', width: 390, height: 844 },
];
const LABELS = { normal: 'normal', zebra: 'zebra stripes', mean: 'mean curvature H', gauss: 'Gaussian curvature K' };

const isBackground = (r, g, b) =>
  Math.abs(r - BACKGROUND[0]) + Math.abs(g - BACKGROUND[1]) + Math.abs(b - BACKGROUND[2]) <= 24;

/** Dark-to-light and light-to-dark changes along the rows of rect, over drawn pixels only. */
function stripeRuns(img, rect) {
  let changes = 0;
  for (let y = rect.y0; y < rect.y1; y += 2) {
    let last = 0; // -1 dark, +1 light, 0 unknown (background or mid-grey)
    for (let x = rect.x0; x < rect.x1; x++) {
      const i = (y * img.width + x) * img.channels;
      const r = img.data[i], g = img.data[i + 1], b = img.data[i + 2];
      if (isBackground(r, g, b)) { last = 0; continue; }
      const lum = (r + g + b) / 3;
      const now = lum < 50 ? -1 : lum > 200 ? 1 : 0;
      if (now && last && now !== last) changes++;
      if (now) last = now;
    }
  }
  return changes;
}

function countNear(img, rect, rgb, tol) {
  let n = 0;
  for (let y = rect.y0; y < rect.y1; y++) {
    for (let x = rect.x0; x < rect.x1; x++) {
      const i = (y * img.width + x) * img.channels;
      if (Math.abs(img.data[i] - rgb[0]) + Math.abs(img.data[i + 1] - rgb[1]) + Math.abs(img.data[i + 2] - rgb[2]) <= tol) n++;
    }
  }
  return n;
}

for (const size of SIZES) {
  describe(`analysis modes at ${size.width}×${size.height}`, { skip }, () => {
    let h, page;
    const shots = {};
    const state = () => page.evaluate(() => window.__pdesurf.analysis());
    const frame = () => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));

    // The drawn view: the viewport minus the toolbar and title, the status line and (desktop) the panel.
    const viewRect = () => page.evaluate(() => {
      const v = document.getElementById('viewport').getBoundingClientRect();
      const p = document.getElementById('panel').getBoundingClientRect();
      const x1 = p.left > v.left + 100 && p.top < v.bottom ? Math.min(v.right, p.left) : v.right;
      // Below the title (at phone size it sits under the toolbar, on two lines).
      const title = document.getElementById('title-bar').getBoundingClientRect();
      const y0 = Math.max(Math.ceil(v.top) + 56, Math.ceil(title.bottom) + 4);
      return { x0: Math.ceil(v.left), x1: Math.floor(x1), y0, y1: Math.floor(v.bottom) - 50 };
    });

    async function openFolder(name) {
      // At phone size the panel is a sheet opened from the toolbar (web/ui/layout.js).
      if (!(await page.locator('#panel').isVisible())) await page.locator('#toolbar [data-action="panel"]').click();
      const folder = page.locator(`#panel [data-folder="${name}"]`);
      if (await folder.evaluate((el) => el.classList.contains('closed'))) {
        await folder.locator(':scope > .title').click();
        await page.waitForFunction((n) => !document.querySelector(`#panel [data-folder="${n}"]`).classList.contains('transition'), name);
      }
      return folder;
    }

    // A screenshot of the view and its rect. At phone size the Controls sheet is closed first
    // (its toolbar button), so the surface is measured at the size a user sees it; openFolder
    // reopens it.
    async function viewShot(name) {
      if (size.name === 'phone' && (await page.locator('#panel').isVisible())) {
        await page.locator('#toolbar [data-action="panel"]').click();
        await frame();
      }
      const rect = await viewRect();
      return { img: await shoot(page, name), rect };
    }

    async function setShading(mode) {
      await openFolder('analysis');
      const select = page.locator('#panel [data-analysis="shading"] select');
      await select.scrollIntoViewIfNeeded();
      await select.selectOption(LABELS[mode]);
      // Done when drawn in that mode, or when the legend says why it cannot be (old module).
      await page.waitForFunction((m) => {
        const a = window.__pdesurf.analysis();
        return a.settings.shading === m && (a.mode === m || (a.legend && a.legend.message && !/computing/.test(a.legend.message)));
      }, mode, { timeout: 20_000 });
      await frame();
    }

    before(async () => {
      h = await startHarness();
      page = await h.open(`/web/#example=${EXAMPLE}`);
      if (size.width !== 1280) {
        // Reload at phone size: the page picks its phone layout (gallery closed) on start.
        await page.setViewportSize({ width: size.width, height: size.height });
        await page.reload();
        await waitReady(page);
      }
      const s = await state();
      assert.equal(s.mode, 'normal');
    });
    after(async () => {
      await h?.close();
    });

    it('keeps the view visible and every control reachable', async () => {
      const layout = await page.evaluate(() => {
        const r = (id) => document.getElementById(id).getBoundingClientRect().toJSON();
        const v = r('viewport');
        const hit = document.elementFromPoint(v.left + v.width / 2, v.top + v.height / 2);
        return { view: v, panel: r('panel'), hitCanvas: hit?.tagName === 'CANVAS', gallery: r('gallery') };
      });
      assert.ok(layout.view.width >= size.width * 0.4 && layout.view.height >= size.height * 0.4,
        `the view is too small: ${JSON.stringify(layout.view)}`);
      assert.ok(layout.hitCanvas, 'something covers the centre of the view');
      // The panel lies beside (desktop) or under (phone) the view, within the window.
      assert.ok(layout.panel.right <= size.width + 1 && layout.panel.bottom <= size.height + 1);
      const overlapX = Math.min(layout.view.right, layout.panel.right) - Math.max(layout.view.left, layout.panel.left);
      const overlapY = Math.min(layout.view.bottom, layout.panel.bottom) - Math.max(layout.view.top, layout.panel.top);
      assert.ok(overlapX <= 1 || overlapY <= 1, `the panel covers the view: ${JSON.stringify(layout)}`);
      for (const key of ['shading', 'wireframe']) {
        await openFolder('analysis');
        const c = page.locator(`#panel [data-analysis="${key}"]`);
        await c.scrollIntoViewIfNeeded();
        const box = await c.boundingBox();
        assert.ok(box && box.y >= 0 && box.y + box.height <= size.height && box.x >= 0 && box.x + box.width <= size.width,
          `${key} control is out of reach: ${JSON.stringify(box)}`);
      }
    });

    it('normal shading draws the two patch colours', async () => {
      await setShading('normal');
      const { img, rect } = await viewShot(`analysis-normal-${size.name}.png`);
      shots.normal = { img, rect };
      assert.equal((await state()).legend, null, 'a legend in normal shading');
      assert.equal(await page.locator('#curvature-legend').isVisible(), false);
    });

    it('zebra stripes alternate many times across the surface and follow the stripe width', async () => {
      await setShading('zebra');
      const { img, rect } = await viewShot(`analysis-zebra-${size.name}.png`);
      shots.zebra = { img, rect };
      const runs = stripeRuns(img, rect);
      const normalRuns = stripeRuns(shots.normal.img, shots.normal.rect);
      const want = size.name === 'phone' ? 60 : 200;
      assert.ok(runs > want, `only ${runs} dark/light changes in zebra mode`);
      assert.ok(runs > 10 * Math.max(normalRuns, 1), `zebra ${runs} vs normal ${normalRuns} changes`);
      // Wider stripes: fewer changes.
      await openFolder('analysis');
      const width = page.locator('#panel [data-analysis="stripeWidth"] input');
      await width.fill('18');
      await width.press('Enter');
      await frame();
      const wide = stripeRuns((await viewShot(`analysis-zebra-wide-${size.name}.png`)).img, rect);
      assert.ok(wide < runs * 0.7, `stripe width 18° gave ${wide} changes, 6° gave ${runs}`);
      await openFolder('analysis');
      await width.fill('6');
      await width.press('Enter');
    });

    it('mean curvature: the module\'s H (cylinder |H| = 1/2r, plane 0), a legend with finite numbers, other colours', async () => {
      await setShading('mean');
      const s = await state();
      assert.ok(s.scale, `no curvature scale; the legend says: ${s.legend?.message}`);
      const cyl = await page.evaluate(() => window.__pdesurf.patchCurvature('cylinder'));
      const plane = await page.evaluate(() => window.__pdesurf.patchCurvature('plane'));
      const H = 1 / (2 * CYLINDER_RADIUS);
      for (const x of cyl.mean) assert.ok(Math.abs(Math.abs(x) - H) < 1e-3 * H, `cylinder H ${cyl.mean}, expected ±${H}`);
      for (const x of [...plane.mean, ...plane.gauss, ...cyl.gauss]) assert.ok(Math.abs(x) < 1e-6, `plane or cylinder K not 0: ${x}`);
      const legend = page.locator('#curvature-legend');
      assert.ok(await legend.isVisible());
      assert.equal(await legend.locator('[data-legend="title"]').textContent(), 'mean curvature H');
      const lo = Number(await legend.locator('[data-legend="min"]').textContent());
      const hi = Number(await legend.locator('[data-legend="max"]').textContent());
      assert.ok(Number.isFinite(lo) && Number.isFinite(hi) && lo < 0 && hi > 0 && Math.abs(lo + hi) < 1e-9 * hi,
        `legend range ${lo} … ${hi} (symmetric)`);
      assert.match(await legend.locator('[data-legend="data"]').textContent(), /^data -?[\d.e-]+ … -?[\d.e-]+/);
      // The legend sits inside the view, small, and lets drags through.
      const [lb, vb] = await page.evaluate(() => [document.getElementById('curvature-legend').getBoundingClientRect().toJSON(),
        document.getElementById('viewport').getBoundingClientRect().toJSON()]);
      assert.ok(lb.left >= vb.left && lb.right <= vb.right && lb.bottom <= vb.bottom, 'the legend leaves the view');
      assert.ok(lb.width * lb.height < 0.2 * vb.width * vb.height, 'the legend covers too much of the view');
      const { img, rect } = await viewShot(`analysis-mean-${size.name}.png`);
      shots.mean = { img, rect };
      const d = drawnDifference(blockAverage(img, rect), blockAverage(shots.normal.img, rect));
      assert.ok(d > 0.3, `the mean-curvature map looks like normal shading (${(100 * d).toFixed(1)} % differs)`);
    });

    it('Gaussian curvature: the cylinder (K = 0) shows the middle of the ramp, the blend other colours', async () => {
      await setShading('gauss');
      const s = await state();
      assert.ok(s.scale && s.scale.min < 0 && s.scale.max > 0, `scale ${JSON.stringify(s.scale)}`);
      const { img, rect } = await viewShot(`analysis-gauss-${size.name}.png`);
      // Cylinder vertices half-way up (t = 0.5 of its range), all around: front or back, all K = 0.
      const points = await page.evaluate(() => {
        const out = [];
        for (let j = 0; j < 64; j += 4) out.push(window.__pdesurf.vertexScreen('cylinder', j * 65 + 32));
        return out;
      });
      let grey = 0, seen = 0;
      for (const p of points) {
        const x = Math.round(p.x), y = Math.round(p.y);
        if (x < rect.x0 || x >= rect.x1 || y < rect.y0 || y >= rect.y1) continue;
        seen++;
        const i = (y * img.width + x) * img.channels;
        const diff = [0, 1, 2].map((c) => Math.abs(img.data[i + c] - MIDDLE_GREY[c]));
        if (Math.max(...diff) <= 10) grey++;
      }
      assert.ok(seen >= 8, `only ${seen} cylinder points in view`);
      assert.ok(grey >= 0.75 * seen, `${grey} of ${seen} cylinder points show K = 0's grey`);
      // The blend is curved both ways somewhere: saturated colours.
      let coloured = 0;
      for (let y = rect.y0; y < rect.y1; y++) {
        for (let x = rect.x0; x < rect.x1; x++) {
          const i = (y * img.width + x) * img.channels;
          const r = img.data[i], g = img.data[i + 1], b = img.data[i + 2];
          if (Math.max(r, g, b) - Math.min(r, g, b) > 60) coloured++;
        }
      }
      assert.ok(coloured > 200, `only ${coloured} saturated pixels in the Gaussian map`);
      const d = drawnDifference(blockAverage(img, rect), blockAverage(shots.mean.img, rect));
      assert.ok(d > 0.1, `the Gaussian map looks like the mean map (${(100 * d).toFixed(1)} %)`);
    });

    it('wireframe overlay goes with any shading mode', async () => {
      await setShading('normal');
      await openFolder('analysis');
      const box = page.locator('#panel [data-analysis="wireframe"] input');
      await box.scrollIntoViewIfNeeded();
      await box.check();
      await frame();
      const s = await state();
      assert.equal(s.wireframe, 3, 'one line set per patch');
      assert.equal(s.mode, 'normal');
      const { img, rect } = await viewShot(`analysis-wireframe-${size.name}.png`);
      const d = drawnDifference(blockAverage(img, rect, 2), blockAverage(shots.normal.img, rect, 2));
      assert.ok(d > 0.1, `the wireframe changed only ${(100 * d).toFixed(1)} % of the drawn area`);
      await setShading('zebra');
      assert.equal((await state()).wireframe, 3, 'the overlay went away with another mode');
      await shoot(page, `analysis-zebra-wireframe-${size.name}.png`);
      await box.uncheck();
      await setShading('normal');
      assert.equal((await state()).wireframe, 0);
    });

    it('lists the joins with their measures and highlights a ticked join on the surface', async () => {
      assert.equal((await state()).report.crossingsChecked, false, 'crossings are checked only while the Joins folder is open');
      const folder = await openFolder('joins');
      // Opening the folder re-solves with the crossing test.
      await page.waitForFunction(() => window.__pdesurf.analysis().report?.crossingsChecked === true);
      const s = await state();
      assert.ok(s.report, 'no join report from the module');
      assert.deepEqual(s.report.crossings, [], 'Fig. 4a crosses nothing');
      assert.match(await folder.locator('.joins-summary').textContent(), /; 0 crossings$/);
      const items = folder.locator('[data-join]');
      assert.equal(await items.count(), s.report.joins.length);
      assert.ok(s.report.joins.length >= 2, 'Fig. 4a has two joins (cylinder and plane)');
      for (const [k, j] of s.report.joins.entries()) {
        const item = items.nth(k);
        const text = await item.textContent();
        assert.ok(text.includes(`“${j.patch}”`) && text.includes(`“${j.surface}”`) && text.includes(j.level), text);
        assert.equal(await item.getAttribute('data-verdict'), j.ok ? 'ok' : 'fail');
        assert.ok(/G0 gap -?[\d.e+-]+/.test(text), `G0 gap not a number: ${text}`);
        assert.ok(/G1 angle -?[\d.e+-]+°/.test(text), `G1 angle not a number: ${text}`);
        // Failing joins start highlighted.
        assert.equal(await item.locator('input[type=checkbox]').isChecked(), !j.ok);
      }
      // The blend closes around v: its seam is listed as a join of the blend with itself.
      const seams = folder.locator('.joins-seam');
      assert.ok(s.report.seams.length >= 1, 'Fig. 4a\'s blend is closed in v');
      assert.equal(await seams.count(), s.report.seams.length);
      for (const [k, j] of s.report.seams.entries()) {
        // (Fig. 4a's data turn at v = 0: the seam is held to G0 there, "sharp in its data".)
        assert.match(await seams.nth(k).textContent(), new RegExp(`^“${j.patch}” seam v0 = v1( \\(sharp in its data\\))?: G[012], gap [-\\d.e+]+, angle [-\\d.e+]+°: ok$`));
        assert.equal(await seams.nth(k).getAttribute('data-verdict'), 'ok');
      }
      const firstOk = s.report.joins.findIndex((j) => j.ok);
      const pick = firstOk >= 0 ? firstOk : 0;
      const box = items.nth(pick).locator('input[type=checkbox]');
      await box.scrollIntoViewIfNeeded();
      const bb = await box.boundingBox();
      assert.ok(bb && bb.y >= 0 && bb.y + bb.height <= size.height, `join checkbox out of reach: ${JSON.stringify(bb)}`);
      if (!(await box.isChecked())) await box.check();
      await frame();
      const after = await state();
      const j = s.report.joins[pick];
      assert.ok(after.highlights.includes(`${j.patch}\u0000${j.end}\u0000${j.surface}\u0000${j.edge}`), `highlights: ${after.highlights}`);
      await folder.evaluate((el) => el.scrollIntoView({ block: 'start' })); // the panel shows the joins list
      await frame();
      const { img, rect } = await viewShot(`analysis-joins-${size.name}.png`);
      const colour = j.ok ? HIGHLIGHT.pick : HIGHLIGHT.fail;
      const n = countNear(img, rect, colour, 60);
      assert.ok(n > (size.name === 'phone' ? 80 : 200), `only ${n} highlight-coloured pixels`);
      await openFolder('joins'); // at phone size the sheet was closed for the screenshot
      await box.uncheck();
      await frame();
      assert.ok(!(await state()).highlights.includes(`${j.patch}\u0000${j.end}\u0000${j.surface}\u0000${j.edge}`), 'unticking kept the highlight');
    });

    it('logged no console error, page error or failed request', () => {
      assert.deepEqual(h.problems, []);
    });
  });
}
