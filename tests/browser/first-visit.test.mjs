// The cold start as scripts/bench-page.mjs measures it (tests/browser/first-visit.mjs): both
// pages it compares load in a fresh browser and mark their first drawn frame; the page's mark
// comes after its first solve is drawn, and that frame built one shader program only (the
// patches' material: overlays, markers and gizmos compile when first used). Times are the
// benchmark's business, not asserted here.
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { skip, startHarness } from './harness.mjs';
import { firstVisit } from './first-visit.mjs';

describe('first visit', { skip }, () => {
  let h;
  before(async () => { h = await startHarness(); });
  after(async () => { await h?.close(); });

  it('the bare three.js page marks its first frame', async () => {
    const r = await firstVisit(`${h.base}/bench/pages/bare-three.html`, () => window.__bareFirstFrameAt);
    assert.deepEqual(r.problems, []);
    assert.ok(r.frameMs > 0, String(r.frameMs));
    assert.ok(r.resources['/node_modules/three/build/three.core.js'] > 0, 'three.js comes unbundled from node_modules');
  });

  it('the production page marks the first frame showing its first solve, built with one shader program', async () => {
    const r = await firstVisit(`${h.base}/app/#example=you2004-fig2a`, () => window.__pdesurf?.firstFrameAt);
    assert.deepEqual(r.problems, []);
    assert.ok(r.readyMs > 0 && r.frameMs > r.readyMs, `ready ${r.readyMs} ms, frame ${r.frameMs} ms`);
    // Three patches (two primaries, one blend) with the patch material: one program.
    assert.deepEqual(r.info, { calls: 3, programs: 1 });
  });
});
