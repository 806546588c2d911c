// Dragging a surface with the page's placement gizmo (web/features/build.js), for the build
// test and scripts/bench-page.mjs: select the surface in the outliner, turn the gizmo on
// (move), find its x arrow on screen and drag it in `steps` pointer moves, one per frame,
// counting frames (requestAnimationFrame), the longest gap between them, long tasks and the
// solves drawn meanwhile. watchFrames and stopFrames are tests/browser/worker.test.mjs's too.

// Hover outward from the pivot along the screen image of world x until the gizmo shows 'X'.
async function findArrow(page) {
  const found = await page.evaluate(() => {
    const h = window.__pdesurf;
    const p = h.modeller().placement.pivot();
    const a = h.screenOf(p);
    const b = h.screenOf([p[0] + 0.01, p[1], p[2]]);
    const len = Math.hypot(b.x - a.x, b.y - a.y);
    return { x: a.x, y: a.y, dx: (b.x - a.x) / len, dy: (b.y - a.y) / len };
  });
  for (let r = 20; r <= 240; r += 6) {
    const at = { x: found.x + r * found.dx, y: found.y + r * found.dy };
    await page.mouse.move(at.x, at.y);
    if ((await page.evaluate(() => window.__pdesurf.modeller().placement.axis())) === 'X') return { ...at, dx: found.dx, dy: found.dy };
  }
  throw new Error('no x arrow found on the gizmo');
}

/** Count frames from now on (requestAnimationFrame), the longest gap and long tasks. */
export function watchFrames(page) {
  return page.evaluate(() => {
    const w = { frames: 0, maxGap: 0, last: performance.now(), longTasks: [] };
    const tick = (t) => {
      w.frames++;
      w.maxGap = Math.max(w.maxGap, t - w.last);
      w.last = t;
      if (!w.stop) requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
    new PerformanceObserver((list) => { for (const e of list.getEntries()) w.longTasks.push(Math.round(e.duration)); })
      .observe({ type: 'longtask' });
    window.__frames = w;
  });
}

/** Stop counting: { frames, maxGap, longTasks, solves }. */
export function stopFrames(page) {
  return page.evaluate(() => {
    window.__frames.stop = true;
    return { frames: window.__frames.frames, maxGap: window.__frames.maxGap, longTasks: window.__frames.longTasks, solves: window.__pdesurf.solveCount };
  });
}

// One pointer move per frame along (dx, dy) from `at`, the button held.
async function drag(page, at, steps, pixels) {
  await page.mouse.move(at.x, at.y);
  await page.mouse.down();
  const t0 = Date.now();
  for (let k = 1; k <= steps; k++) {
    await page.mouse.move(at.x + pixels * k * at.dx, at.y + pixels * k * at.dy);
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));
  }
  return Date.now() - t0;
}

/** The same drag orbiting the camera (renders only, no solve): the frames' baseline. */
export async function orbitDrag(page, { steps = 60, pixels = 2 } = {}) {
  const box = await page.locator('#viewport canvas').boundingBox();
  await watchFrames(page);
  const dragMs = await drag(page, { x: box.x + box.width * 0.3, y: box.y + box.height * 0.7, dx: 1, dy: 0 }, steps, pixels);
  const during = await stopFrames(page);
  await page.mouse.up();
  return { dragMs, ...during, fps: (1000 * during.frames) / dragMs };
}

/** Select the patch and show its placement gizmo in move mode. */
export async function showGizmo(page, name) {
  await page.locator(`#panel [data-patch="${name}"] [data-action="select"]`).click();
  await page.locator('#panel [data-placement="gizmo"] select').selectOption('move');
}

/** Drag the patch's x arrow; shown: its gizmo is already up (showGizmo). */
export async function dragSurface(page, name, { steps = 60, pixels = 2, shown = false } = {}) {
  if (!shown) await showGizmo(page, name);
  const at = await findArrow(page);
  const solvesBefore = await page.evaluate(() => window.__pdesurf.solveCount);
  await watchFrames(page);
  const dragMs = await drag(page, at, steps, pixels);
  const during = await stopFrames(page);
  await page.mouse.up();
  return { dragMs, frames: during.frames, fps: (1000 * during.frames) / dragMs, maxGap: during.maxGap,
    longTasks: during.longTasks, solvesDuring: during.solves - solvesBefore };
}
