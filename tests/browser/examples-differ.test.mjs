// Every example of examples/index.json, screenshotted at 1280×800 (build/browser/examples/),
// must look different from every other one: two examples that draw (nearly) the same
// picture are a mislabelled or copied example. The measure (image-diff.mjs): of the
// view's drawn area (blocks of 4×4 pixels where either picture shows a surface), the
// fraction that differs visibly. Pairs under MIN_DIFFERENCE fail unless ALLOWED says why.
// All scores go to build/browser/examples-differ.json, closest pairs first.
//   node --test tests/browser/examples-differ.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { skip, startHarness, exampleIndex, hooks, solvedAfter, shoot, OUT_DIR } from './harness.mjs';
import { blockAverage, drawnDifference } from './image-diff.mjs';

// Threshold (docs/page-analysis.md): the same scene drawn twice scores 0 (rendering is
// deterministic; the test checks it). Measured on the 42 examples (861 pairs): before
// the examples' rework, seed 004's vases under forces (Figs. 2a, 3a-d) scored 1.5-3.6 %
// and seed 000's Figs. 3a/3b (a slight bulge) 4.3 %, pairs the team judged too alike by
// eye; after it, those score 15-24 %, seed 000's new Fig. 3b (p0 = 300) against Fig. 3d
// scores 3.6 % (two near-identical convex bulges), and the closest pair that reads as two
// figures (seed 000 Figs. 3c/3e: a waist vs a thinner waist) 8 %. 5 % sits in that gap.
export const MIN_DIFFERENCE = 0.05;

// Pairs that may legitimately look alike, each with the reason: "idA|idB" -> why.
export const ALLOWED = new Map([
]);

const pairKey = (a, b) => (a < b ? `${a}|${b}` : `${b}|${a}`);

describe('every example draws its own picture', { skip }, () => {
  let h, page;
  const pictures = new Map(); // id -> block-averaged view
  before(async () => {
    h = await startHarness();
  });
  after(async () => {
    await h?.close();
  });

  it('screenshots every example', { timeout: 600_000 }, async () => {
    const index = exampleIndex();
    fs.mkdirSync(path.join(OUT_DIR, 'examples'), { recursive: true });
    page = await h.open(`/web/#example=${encodeURIComponent(index[0].id)}`);
    // The same rectangle for every example: the view between gallery and panel, below
    // the title bar and above the status line (both carry per-example text).
    const rect = await page.evaluate(() => {
      const v = document.getElementById('viewport').getBoundingClientRect();
      const p = document.getElementById('panel').getBoundingClientRect();
      return { x0: Math.ceil(v.left), x1: Math.floor(Math.min(v.right, p.left)), y0: 40, y1: Math.floor(v.bottom) - 50 };
    });
    for (const [k, entry] of index.entries()) {
      if (k > 0) {
        const before = await hooks(page);
        await page.evaluate((id) => { location.hash = 'example=' + encodeURIComponent(id); }, entry.id);
        await page.waitForFunction((id) => window.__pdesurf.exampleId === id, entry.id, { timeout: 20_000 });
        await solvedAfter(page, before.solveCount);
      }
      const now = await hooks(page);
      assert.equal(now.lastError, null, `${entry.id}: ${now.lastError}`);
      const img = await shoot(page, path.join('examples', `${entry.id}.png`));
      pictures.set(entry.id, blockAverage(img, rect));
    }
    assert.equal(pictures.size, index.length);

    // The measure's own check: the first example again must give the same picture.
    const before = await hooks(page);
    await page.evaluate((id) => { location.hash = 'example=' + encodeURIComponent(id); }, index[0].id);
    await page.waitForFunction((id) => window.__pdesurf.exampleId === id, index[0].id, { timeout: 20_000 });
    await solvedAfter(page, before.solveCount);
    const again = blockAverage(await shoot(page, path.join('examples', `${index[0].id}-again.png`)), rect);
    const d = drawnDifference(again, pictures.get(index[0].id));
    assert.ok(d < 0.002, `${index[0].id} drawn twice differs on ${(100 * d).toFixed(2)} % of its area`);
  });

  it(`no two examples differ on less than ${100 * MIN_DIFFERENCE} % of the drawn area`, () => {
    const ids = [...pictures.keys()];
    assert.ok(ids.length > 1, 'no screenshots (the first test failed)');
    const scores = [];
    for (let i = 0; i < ids.length; i++) {
      for (let j = i + 1; j < ids.length; j++) {
        scores.push({ a: ids[i], b: ids[j], difference: drawnDifference(pictures.get(ids[i]), pictures.get(ids[j])) });
      }
    }
    scores.sort((x, y) => x.difference - y.difference);
    fs.writeFileSync(path.join(OUT_DIR, 'examples-differ.json'), JSON.stringify(scores, null, 1));
    const alike = scores.filter((s) => s.difference < MIN_DIFFERENCE && !ALLOWED.has(pairKey(s.a, s.b)));
    const stale = [...ALLOWED.keys()].filter((k) => !scores.some((s) => pairKey(s.a, s.b) === k && s.difference < MIN_DIFFERENCE));
    assert.deepEqual(alike.map((s) => `${s.a} ~ ${s.b}: ${(100 * s.difference).toFixed(2)} %`), [],
      'examples that draw nearly the same picture (build/browser/examples/)');
    assert.deepEqual(stale, [], 'allowed pairs that now differ: take them off ALLOWED');
  });
});
