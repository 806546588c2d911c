// Shared set-up of the browser tests: the static server, Debian's Chromium through
// playwright-core (never a downloaded browser), pages that record every console
// error, page error and failed request, and helpers over window.__pdesurf.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { startServer } from '../../scripts/static-server.mjs';
import { decodePng, pixelStats } from './png-decode.mjs';

export const REPO = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
// Another site root (with examples/, web/, node_modules/) can be tested in place of the repo.
export const ROOT = process.env.PDESURF_TEST_ROOT ? path.resolve(process.env.PDESURF_TEST_ROOT) : REPO;
const WASM_DIR = process.env.PDESURF_WASM_DIR || path.join(REPO, 'build', 'wasm');
export const OUT_DIR = path.join(REPO, 'build', 'browser');
const CHROMIUM = '/usr/bin/chromium';
export const BACKGROUND = [0x20, 0x24, 0x2b]; // web/viewer/viewer.js BACKGROUND
const CHROMIUM_ARGS = [
  '--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync',
  '--use-gl=angle', '--use-angle=swiftshader',
  // Headless Chromium 156 sometimes (about one launch in three) preloads its omnibox popup's
  // WebUI in a renderer of its own, about a second of CPU while the page under test loads:
  // on two cores that was most of the first-visit benchmark's spread (pairs 1.0-2.7x).
  '--disable-features=PreloadTopChromeWebUI,WebUIOmniboxPopup,WebUIOmniboxFullPopup,WebUIOmniboxAimPopup',
];

export const skip = fs.existsSync(CHROMIUM) ? false : `${CHROMIUM} is missing (apt-get install chromium); browser tests skipped`;

export const exampleIndex = () => JSON.parse(fs.readFileSync(path.join(ROOT, 'examples', 'index.json'), 'utf8')).examples;

/**
 * Debian's Chromium with a new temporary profile (a persistent context is how playwright
 * takes --user-data-dir): { context, close() }, close() also removing the profile.
 */
export async function launchChromium({ viewport = { width: 1280, height: 800 } } = {}) {
  const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'pdesurf-chromium-'));
  const { chromium } = await import('playwright-core');
  const context = await chromium.launchPersistentContext(userDataDir, { executablePath: CHROMIUM, args: CHROMIUM_ARGS, headless: true, viewport });
  return {
    context,
    async close() {
      await context.close();
      fs.rmSync(userDataDir, { recursive: true, force: true });
    },
  };
}

/** Start server + browser. Returns { base, problems, context, open(url) -> page, close() }. */
export async function startHarness() {
  assert.ok(fs.existsSync(path.join(WASM_DIR, 'pdesurf.js')), `no wasm module in ${WASM_DIR}: build it first (scripts/build-wasm)`);
  assert.ok(fs.existsSync(path.join(ROOT, 'examples', 'index.json')), `no examples/index.json under ${ROOT}`);
  assert.ok(fs.existsSync(path.join(ROOT, 'node_modules', 'three')), 'node_modules/three is missing: run npm ci');
  fs.mkdirSync(OUT_DIR, { recursive: true });
  const server = await startServer({ port: 0, root: ROOT, wasmDir: WASM_DIR });
  const base = `http://127.0.0.1:${server.address().port}`;
  const browser = await launchChromium();
  const { context } = browser;
  const problems = []; // console errors, page errors, failed requests
  let closingAll = false;
  let first = context.pages()[0];

  return {
    base,
    problems,
    context, // for context-wide init scripts and response listeners
    /**
     * A fresh page (closing none) loading `url` and waiting for its first draw or error;
     * viewport: { width, height } to load it at another size than 1280×800.
     */
    async open(url, { wait = true, viewport = null } = {}) {
      const page = first || (await context.newPage());
      first = null;
      if (viewport) await page.setViewportSize(viewport);
      page.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
      page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
      // A request the test cuts short by closing the page or sending it to another URL (a lazy
      // module still loading, e.g. the link's deflater on a loaded machine) is the test's
      // doing, not a failure of the page.
      let closing = false;
      let leaving = 0;
      const closePage = page.close.bind(page);
      page.close = (...args) => { closing = true; return closePage(...args); };
      const gotoPage = page.goto.bind(page);
      page.goto = async (...args) => {
        leaving++;
        try {
          return await gotoPage(...args);
        } finally {
          leaving--;
        }
      };
      page.on('requestfailed', (r) => {
        if ((closing || closingAll || leaving > 0) && r.failure()?.errorText === 'net::ERR_ABORTED') return;
        problems.push(`request failed: ${r.url()} ${r.failure()?.errorText}`);
      });
      await gotoPage(url.startsWith('http') ? url : `${base}${url}`); // its first load is the page's own
      if (wait) await waitReady(page);
      return page;
    },
    async close() {
      closingAll = true;
      await browser.close();
      await new Promise((r) => server.close(r));
    },
  };
}

export async function waitReady(page) {
  await page.waitForFunction(() => window.__pdesurf && (window.__pdesurf.ready || window.__pdesurf.lastError),
    null, { timeout: 30_000 });
}

export const hooks = (page) => page.evaluate(() => {
  const h = window.__pdesurf;
  return { ready: h.ready, solveCount: h.solveCount, lastError: h.lastError, exampleId: h.exampleId,
    notice: h.notice, lastLink: h.lastLink, checksum: h.checksum(), vertexCount: h.vertexCount(), camera: h.camera() };
});

/** Wait until a solve after `count` has happened and the frame is painted. */
export async function solvedAfter(page, count) {
  await page.waitForFunction((n) => window.__pdesurf.solveCount > n, count, { timeout: 20_000 });
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));
  return hooks(page);
}

/** Screenshot into build/browser/<name>, decoded. */
export async function shoot(page, name) {
  return decodePng(await page.screenshot({ path: path.join(OUT_DIR, name) }));
}

/** Pixel statistics of the 3D view minus the gallery, the panel, the title bar and the status line. */
export async function viewStats(page, img) {
  const r = await page.evaluate(() => {
    const view = document.getElementById('viewport').getBoundingClientRect();
    const panel = document.getElementById('panel').getBoundingClientRect();
    // A docked panel ends the view on the right; a sheet (compact screens) or no panel does not.
    const right = panel.width > 0 && panel.left > view.left ? Math.min(view.right, panel.left) : view.right;
    return { x0: Math.ceil(view.left), x1: Math.floor(right) };
  });
  return pixelStats(img, { x0: r.x0, y0: 40, x1: r.x1, y1: img.height - 50 }, BACKGROUND);
}

export const sameChecksum = (a, b) => Math.abs(a - b) <= 1e-9 * Math.abs(b);

/**
 * A cold load of `url` in a new page of the harness `h` (HTTP cache cleared and disabled):
 * { ms: navigation start to the first surface, bytes: encoded bytes the page received,
 *   encodings: path -> Content-Encoding, state: hooks }. tests/browser/app.test.mjs and
 * scripts/bench-page.mjs.
 */
export async function coldStart(h, url) {
  const page = await h.context.newPage();
  const cdp = await h.context.newCDPSession(page);
  await cdp.send('Network.enable');
  // The worker's requests go through the same HTTP cache but not this page's session: clear it.
  await cdp.send('Network.clearBrowserCache');
  await cdp.send('Network.setCacheDisabled', { cacheDisabled: true });
  let bytes = 0;
  const encodings = {};
  cdp.on('Network.loadingFinished', (e) => { bytes += e.encodedDataLength; });
  page.on('response', async (r) => { encodings[new URL(r.url()).pathname] = (await r.allHeaders())['content-encoding'] ?? null; });
  await page.goto(url);
  await page.waitForFunction(() => window.__pdesurf?.ready || window.__pdesurf?.lastError, null, { timeout: 30_000 });
  const ms = await page.evaluate(() => window.__pdesurf.readyAt);
  const state = await hooks(page);
  await page.close();
  return { ms, bytes, encodings, state };
}

/**
 * From now on in every page of the harness's context: content-security-policy violations in
 * window.__cspViolations ("directive: blocked URI"), and the path of every request in the
 * array returned.
 */
export async function recordRequestsAndCsp(h) {
  const requests = [];
  await h.context.addInitScript(() => {
    window.__cspViolations = [];
    document.addEventListener('securitypolicyviolation', (e) => window.__cspViolations.push(`${e.violatedDirective}: ${e.blockedURI}`));
  });
  h.context.on('request', (r) => requests.push(new URL(r.url()).pathname));
  return requests;
}
