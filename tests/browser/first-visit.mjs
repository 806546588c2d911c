// A first visit, measured as a visitor sees it: a fresh Chromium with a new profile per load
// (no HTTP cache, no compiled-code or shader cache), navigation to the first frame that
// shows the content. scripts/bench-page.mjs (the cold start against a bare three.js page)
// and tests/browser/first-visit.test.mjs.
import { launchChromium } from './harness.mjs';

// Run in every page before its own scripts: the time of its first WebGL draw call, the moment
// a page hands its first surface to the GPU, measured the same way on any page; and of its
// first read of a program's link status (which waits for the GPU process to have linked it).
function markFirstDrawCall() {
  const marks = { drawElements: '__firstDrawCallAt', drawArrays: '__firstDrawCallAt', drawElementsInstanced: '__firstDrawCallAt',
    drawArraysInstanced: '__firstDrawCallAt', drawRangeElements: '__firstDrawCallAt', getProgramParameter: '__firstProgramCheckAt' };
  for (const proto of [globalThis.WebGLRenderingContext?.prototype, globalThis.WebGL2RenderingContext?.prototype]) {
    for (const [name, mark] of Object.entries(marks)) {
      const call = proto?.[name];
      if (!call) continue;
      proto[name] = function marked(...args) {
        window[mark] ??= performance.now();
        return call.apply(this, args);
      };
    }
  }
}

/**
 * Loads `url` in a browser of its own and waits until `frameMark()` (run in the page, e.g.
 * () => window.__pdesurf?.firstFrameAt) is a number, then, on pdesurf's page, until it is
 * ready (its first result handled and its panel built, after that frame): { frameMs,
 * drawCallMs (its first WebGL draw call), programCheckMs (its first read of a program's
 * status), marks ({ name: ms } of its pdesurf: marks),
 * readyMs (window.__pdesurf.readyAt), resources: { path: responseEnd ms }, info (the first
 * frame's { calls, programs }), solvedAhead (the first solve came from the worker's solve
 * ahead), surfaceBeforePanel (that solve came in time to be drawn before the panel was
 * built), problems: [console errors, page errors] }; those five null on another page.
 */
export async function firstVisit(url, frameMark, { viewport = { width: 1280, height: 800 } } = {}) {
  const browser = await launchChromium({ viewport });
  const { context } = browser;
  try {
    await context.addInitScript(markFirstDrawCall);
    const page = context.pages()[0] || (await context.newPage());
    const problems = [];
    page.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
    page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
    await page.goto(url);
    await page.waitForFunction(frameMark, null, { timeout: 60_000 });
    const frameMs = await page.evaluate(frameMark);
    await page.waitForFunction(() => !window.__pdesurf || window.__pdesurf.ready, null, { timeout: 60_000 });
    const seen = await page.evaluate((ms) => ({
      frameMs: ms,
      drawCallMs: window.__firstDrawCallAt ?? null,
      programCheckMs: window.__firstProgramCheckAt ?? null,
      // The page's own marks on the way (web/main.js, solver-client.js, viewer.js).
      marks: Object.fromEntries(performance.getEntriesByType('mark').filter((m) => m.name.startsWith('pdesurf:')).map((m) => [m.name.slice(8), m.startTime])),
      readyMs: window.__pdesurf?.readyAt ?? null,
      resources: Object.fromEntries(performance.getEntriesByType('resource').map((r) => [new URL(r.name).pathname, r.responseEnd])),
      info: window.__pdesurf?.firstFrameInfo ?? null,
      solvedAhead: window.__pdesurf?.lastSolve?.solvedAhead ?? null,
      workerMs: window.__pdesurf?.lastSolve?.workerMs ?? null, // the first solve's time in the worker (its wasm)
      surfaceBeforePanel: window.__pdesurf?.surfaceBeforePanel ?? null,
    }), frameMs);
    return { ...seen, problems };
  } finally {
    await browser.close();
  }
}
