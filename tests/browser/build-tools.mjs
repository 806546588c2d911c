// Shared by the browser tests that build in the page (build.test.mjs, pick-ends.test.mjs):
// picking a drawn border with the mouse, an edit that solves, the link checked by the CLI.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { hooks, solvedAfter, REPO } from './harness.mjs';

export const CLI = process.env.PDESURF_CLI ?? path.join(REPO, 'build', 'native', 'pdesurf');

/**
 * Screen point of a drawn patch's border: t0/u0 is the grid column i = 0, t1/u1 i = nu; the
 * vertex at `along` (0..1) of its v.
 */
export function borderPoint(page, patch, border, along = 0.5) {
  return page.evaluate(([patch, border, along]) => {
    const h = window.__pdesurf;
    const { nu, nv } = h.lastSolve;
    const i = border === 't0' || border === 'u0' ? 0 : nu;
    return h.vertexScreen(patch, Math.round(nv * along) * (nu + 1) + i);
  }, [patch, border, along]);
}

/** Hover the border (the picker must name it), then click it. */
export async function clickBorder(page, patch, border, along = 0.5) {
  const p = await borderPoint(page, patch, border, along);
  await page.mouse.move(p.x - 20, p.y - 20);
  await page.mouse.move(p.x, p.y, { steps: 3 });
  const st = await page.evaluate(() => window.__pdesurf.modeller().borders.state());
  assert.deepEqual(st.hovered, { patch, border }, `hover over ${patch} ${border}`);
  await page.mouse.click(p.x, p.y);
}

/** An edit that solves: run it and wait for the solve. */
export async function solving(page, action) {
  const n = (await hooks(page)).solveCount;
  await action();
  return solvedAfter(page, n);
}

/** The link in the address bar, decoded by the CLI and checked there: { scene, report }. */
export function checkLink(url) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'pdesurf-build-'));
  const decoded = spawnSync(CLI, ['decode-link', url], { encoding: 'utf8' });
  assert.equal(decoded.status, 0, decoded.stderr);
  const file = path.join(dir, 'scene.json');
  fs.writeFileSync(file, decoded.stdout);
  const checked = spawnSync(CLI, ['check', file, '--json'], { encoding: 'utf8' });
  fs.rmSync(dir, { recursive: true, force: true });
  assert.equal(checked.status, 0, checked.stdout + checked.stderr);
  return { scene: JSON.parse(decoded.stdout), report: JSON.parse(checked.stdout) };
}
