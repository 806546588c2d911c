// The page runs under the static server's Content-Security-Policy without a single
// violation: the importmap is allowed by its hash, no inline handler is left, lil-gui's
// injected stylesheet and the wasm module are allowed. Violations are caught twice: the
// page's securitypolicyviolation events and Chromium's console messages about the CSP.
// And the policy bites: an injected inline handler is refused; the message for scripts that
// cannot load, once an inline onerror, still shows.
//   node --test tests/browser/csp.test.mjs
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { skip, startHarness, hooks, shoot, viewStats } from './harness.mjs';

describe('content security policy', { skip }, () => {
  let h, page;
  const documents = []; // responses of top-level documents
  const cspMessages = []; // console messages of any type that mention the CSP
  before(async () => {
    h = await startHarness();
    await h.context.addInitScript(() => {
      window.__cspViolations = [];
      document.addEventListener('securitypolicyviolation', (e) => {
        window.__cspViolations.push(`${e.violatedDirective}: ${e.blockedURI} ${e.sourceFile}:${e.lineNumber}`);
      });
    });
    h.context.on('response', (r) => { if (r.request().resourceType() === 'document') documents.push(r); });
    h.context.on('console', (m) => { if (/Content Security Policy/i.test(m.text())) cspMessages.push(m.text()); });
  });
  after(async () => {
    await h?.close();
  });

  it('draws the first surface with no violation', async () => {
    page = await h.open('/web/');
    const drawn = await hooks(page);
    assert.equal(drawn.lastError, null, `page reported: ${drawn.lastError}`);
    assert.equal(drawn.ready, true);
    assert.ok(drawn.vertexCount > 0);
    // lil-gui's panel is built (its injected stylesheet is covered by the violation checks below).
    assert.ok(await page.locator('#panel .lil-gui').count() > 0, 'no lil-gui panel');
    const img = await shoot(page, 'csp-1280.png');
    const stats = await viewStats(page, img);
    assert.ok(stats.fraction > 0.03, `canvas looks blank: ${JSON.stringify(stats)}`);

    const csp = await documents.at(-1).headerValue('content-security-policy');
    assert.match(csp ?? '', /script-src 'self' [^;]*'sha256-[A-Za-z0-9+/]+=*'/);
    assert.doesNotMatch(csp, /script-src[^;]*'unsafe-inline'/);
    assert.doesNotMatch(csp, /'unsafe-eval'/, 'the wasm module is linked with -sDYNAMIC_EXECUTION=0: no eval needed');
    assert.deepEqual(await page.evaluate(() => window.__cspViolations), []);
    assert.deepEqual(cspMessages, []);
    assert.deepEqual(h.problems, []);
  });

  it('the production page (its boot script inline, allowed by its hash) draws with no violation, its worker solving ahead', async () => {
    const app = await h.open('/app/#example=you2004-fig4a');
    const drawn = await hooks(app);
    assert.equal(drawn.lastError, null, `page reported: ${drawn.lastError}`);
    assert.equal(drawn.exampleId, 'you2004-fig4a');
    assert.equal(await app.evaluate(() => window.__pdesurf.lastSolve.solvedAhead), true, 'the inline boot script started the worker with the hash');
    const html = await (await app.request.get(`${h.base}/app/`)).text();
    assert.match(html, /<script data-worker="\.\/solver-worker\.js">[^<]*new Worker/, 'boot.js inlined');
    assert.ok(!html.includes('src="./boot.js"'));
    assert.deepEqual(await app.evaluate(() => window.__cspViolations), []);
    assert.deepEqual(cspMessages, []);
    assert.deepEqual(h.problems, []);
    await app.close();
  });

  it('refuses an inline event handler', async () => {
    await page.evaluate(() => {
      const img = document.createElement('img');
      img.setAttribute('onerror', 'window.__inlineRan = true');
      img.src = 'data:,';
      document.body.append(img);
    });
    await page.waitForFunction(() => window.__cspViolations.length > 0, null, { timeout: 5_000 });
    assert.equal(await page.evaluate(() => window.__inlineRan), undefined);
    const directives = await page.evaluate(() => window.__cspViolations.map((v) => v.split(':')[0]));
    assert.deepEqual(directives, ['script-src-attr']);
  });

  it('still says so when the page scripts cannot load (web/load-check.js)', async () => {
    await h.context.route('**/three.module.js', (route) => route.abort());
    try {
      const broken = await h.open('/web/', { wait: false });
      await broken.waitForFunction(() => document.getElementById('status').className === 'error', null,
        { timeout: 10_000 });
      assert.match(await broken.locator('#status').textContent(), /cannot load the page scripts/);
      assert.deepEqual(await broken.evaluate(() => window.__cspViolations), []);
    } finally {
      await h.context.unroute('**/three.module.js');
    }
  });
});
