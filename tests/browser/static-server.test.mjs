// The static server the modeller and the browser tests run on: MIME types the
// browser insists on, plain-text 404s, the /wasm/ mapping, no path traversal, nothing
// outside what the page needs (no .git, build, sources, dotfiles, symlinks out of a
// tree), and the security headers (CSP with the importmap's hash) on every response.
import crypto from 'node:crypto';
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import { startServer, inlineScriptHashes } from '../../scripts/static-server.mjs';

// Raw request, so "../" reaches the server un-normalised (fetch would clean it up).
function get(port, rawPath, method = 'GET') {
  return new Promise((resolve, reject) => {
    const req = http.request({ host: '127.0.0.1', port, path: rawPath, method }, (res) => {
      let body = '';
      res.setEncoding('utf8');
      res.on('data', (c) => (body += c));
      res.on('end', () => resolve({ status: res.statusCode, headers: res.headers, body }));
    });
    req.on('error', reject);
    req.end();
  });
}

const IMPORTMAP = '\n  { "imports": { "three": "/node_modules/three/build/three.module.js" } }\n  ';
const PAGE = `<!doctype html><title>t</title><script type="importmap">${IMPORTMAP}</script>`;
const sha256 = (text) => crypto.createHash('sha256').update(text).digest('base64');
const HEADERS = ['content-security-policy', 'x-content-type-options', 'referrer-policy',
  'cross-origin-opener-policy', 'cross-origin-resource-policy'];

describe('static server', () => {
  let server, port, tmp;

  before(async () => {
    tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'pdesurf-server-'));
    const root = path.join(tmp, 'site');
    const wasm = path.join(tmp, 'wasm-out');
    const put = (file, text) => {
      fs.mkdirSync(path.dirname(file), { recursive: true });
      fs.writeFileSync(file, text);
    };
    put(path.join(root, 'web', 'index.html'), PAGE);
    put(path.join(root, 'web', 'a.js'), 'export {};');
    fs.symlinkSync('a.js', path.join(root, 'web', 'b.js')); // a symlink inside its tree is fine
    put(path.join(root, 'examples', 'data.json'), '{}');
    put(path.join(root, 'docs', 'page.md'), '# the page'); // the help overlay links the docs
    put(path.join(wasm, 'pdesurf.wasm'), Buffer.from([0, 0x61, 0x73, 0x6d, 1, 0, 0, 0]));
    put(path.join(tmp, 'secret.txt'), 'outside the root');
    // What the page does not need, next to what it does.
    for (const f of ['.git/HEAD', 'build/wasm/pdesurf.js', 'package.json', 'cpp/core.cpp', 'tests/t.mjs',
      'scripts/serve', 'web/.env', 'web/.hidden/x.js', 'examples/.DS_Store', 'node_modules/other/index.js']) {
      put(path.join(root, f), 'outside the root');
    }
    put(path.join(wasm, 'CMakeCache.txt'), 'outside the root');
    // The .3dm writer's worker (sources and build) and the package it loads.
    put(path.join(root, 'web', 'cad', 'rhino-worker.js'), 'export {};');
    put(path.join(root, 'build', 'web', 'rhino-worker.js'), 'export {};');
    put(path.join(root, 'node_modules', 'rhino3dm', 'rhino3dm.wasm'), Buffer.from([0, 0x61, 0x73, 0x6d, 1, 0, 0, 0]));
    // node_modules itself a symlink (as in a git worktree): three/ is still its real tree.
    put(path.join(tmp, 'nm', 'three', 'build', 'three.module.js'), 'export {};');
    fs.symlinkSync(path.join(tmp, 'nm'), path.join(root, 'node_modules', 'three-link'));
    fs.symlinkSync(path.join(tmp, 'nm', 'three'), path.join(root, 'node_modules', 'three'));
    // Symlinks out of their trees: a directory, a file, and the wasm dir's header shim.
    fs.symlinkSync('/etc', path.join(root, 'web', 'leak'));
    fs.symlinkSync(path.join(tmp, 'secret.txt'), path.join(root, 'examples', 'leak.json'));
    put(path.join(tmp, 'secret.js'), 'outside the root');
    fs.symlinkSync(path.join(tmp, 'secret.js'), path.join(wasm, 'pdesurf.js'));
    fs.mkdirSync(path.join(wasm, 'shim-include'));
    fs.symlinkSync(tmp, path.join(wasm, 'shim-include', 'up'));
    server = await startServer({ port: 0, root, wasmDir: wasm, appDir: path.join(root, 'build', 'web') });
    port = server.address().port;
    assert.ok(port > 0);
  });

  after(async () => {
    await new Promise((r) => server.close(r));
    fs.rmSync(tmp, { recursive: true, force: true });
  });

  it('redirects / to /web/ and serves its index.html', async () => {
    const r = await get(port, '/');
    assert.equal(r.status, 302);
    assert.equal(r.headers.location, '/web/');
    const page = await get(port, '/web/');
    assert.equal(page.status, 200);
    assert.match(page.headers['content-type'], /^text\/html/);
  });

  it('serves the MIME types browsers check', async () => {
    assert.match((await get(port, '/web/a.js')).headers['content-type'], /^text\/javascript/);
    assert.match((await get(port, '/examples/data.json')).headers['content-type'], /^application\/json/);
    const w = await get(port, '/wasm/pdesurf.wasm');
    assert.equal(w.status, 200);
    assert.equal(w.headers['content-type'], 'application/wasm');
  });

  it('answers a missing file with a plain-text 404', async () => {
    for (const p of ['/nope.js', '/wasm/pdesurf.mjs', '/web/missing/']) {
      const r = await get(port, p);
      assert.equal(r.status, 404, p);
      assert.match(r.headers['content-type'], /^text\/plain/, p);
      assert.doesNotMatch(r.body, /<html/i, p);
    }
  });

  it('refuses path traversal, raw or encoded', async () => {
    for (const p of ['/../secret.txt', '/web/../../secret.txt', '/%2e%2e/secret.txt', '/wasm/..%2f..%2fsecret.txt',
      '/wasm/%2e%2e/secret.txt', '/web/..%5c..%5csecret.txt']) {
      const r = await get(port, p);
      assert.notEqual(r.status, 200, p);
      assert.doesNotMatch(r.body, /outside the root/, p);
    }
  });

  it('serves the page, the examples, the wasm module, three and rhino3dm, and nothing else', async () => {
    for (const p of ['/web/b.js', '/examples/data.json', '/docs/page.md', '/wasm/pdesurf.wasm',
      '/node_modules/three/build/three.module.js', '/node_modules/rhino3dm/rhino3dm.wasm']) {
      assert.equal((await get(port, p)).status, 200, p);
    }
    for (const p of ['/.git/HEAD', '/.git/', '/build/wasm/pdesurf.js', '/package.json', '/cpp/core.cpp', '/cpp/',
      '/tests/t.mjs', '/scripts/serve', '/node_modules/other/index.js', '/node_modules/',
      '/node_modules/three-link/three/build/three.module.js', '/wasm/', '/wasm/CMakeCache.txt',
      '/wasm/shim-include/up/secret.txt', '/data.json']) {
      const r = await get(port, p);
      assert.equal(r.status, 404, p);
      assert.doesNotMatch(r.body, /outside the root/, p);
    }
  });

  it('never serves dotfiles or dot-directories', async () => {
    for (const p of ['/web/.env', '/web/.hidden/x.js', '/web/%2eenv', '/examples/.DS_Store', '/web/.hidden/']) {
      const r = await get(port, p);
      assert.equal(r.status, 404, p);
      assert.doesNotMatch(r.body, /outside the root/, p);
    }
  });

  it('does not follow a symlink out of its tree', async () => {
    for (const p of ['/web/leak/hostname', '/web/leak/passwd', '/web/leak/', '/examples/leak.json',
      '/wasm/pdesurf.js']) {
      const r = await get(port, p);
      assert.equal(r.status, 404, p);
      assert.doesNotMatch(r.body, /outside the root|root:/, p);
    }
  });

  it('sends the security headers on every response', async () => {
    const answers = [[await get(port, '/web/'), 200], [await get(port, '/web/a.js', 'HEAD'), 200],
      [await get(port, '/'), 302], [await get(port, '/web'), 301], [await get(port, '/package.json'), 404],
      [await get(port, '/wasm/..%2fsecret.txt'), 403], [await get(port, '/web/', 'POST'), 405]];
    for (const [r, status] of answers) {
      assert.equal(r.status, status);
      for (const h of HEADERS) assert.ok(r.headers[h], `${status}: no ${h}`);
      assert.equal(r.headers['x-content-type-options'], 'nosniff');
      assert.equal(r.headers['referrer-policy'], 'no-referrer');
      assert.equal(r.headers['cross-origin-opener-policy'], 'same-origin');
      assert.equal(r.headers['cross-origin-resource-policy'], 'same-origin');
    }
    const csp = answers[0][0].headers['content-security-policy'];
    assert.match(csp, /(^|; )default-src 'self'(;|$)/);
    assert.match(csp, /(^|; )object-src 'none'(;|$)/);
    assert.match(csp, /(^|; )frame-ancestors 'none'(;|$)/);
    assert.doesNotMatch(csp, /script-src[^;]*'unsafe-inline'/);
  });

  it('allows eval in the .3dm writer\'s worker only', async () => {
    const policy = async (p) => {
      const r = await get(port, p);
      assert.equal(r.status, 200, p);
      return r.headers['content-security-policy'];
    };
    for (const p of ['/web/cad/rhino-worker.js', '/app/rhino-worker.js']) {
      const csp = await policy(p);
      assert.match(csp, /(^|; )script-src 'self' 'wasm-unsafe-eval' 'unsafe-eval'(;|$)/, p);
      assert.match(csp, /(^|; )default-src 'self'(;|$)/, p);
      assert.doesNotMatch(csp, /'unsafe-inline'/, p);
    }
    for (const p of ['/web/', '/web/a.js', '/node_modules/rhino3dm/rhino3dm.wasm']) assert.doesNotMatch(await policy(p), /'unsafe-eval'/, p);
    assert.equal((await get(port, '/node_modules/rhino3dm/rhino3dm.wasm')).headers['content-type'], 'application/wasm');
  });

  it('allows the inline scripts by their hashes, recomputed when a page changes', async () => {
    const scriptSrc = async () =>
      (await get(port, '/web/')).headers['content-security-policy'].match(/script-src ([^;]*)/)[1];
    assert.ok((await scriptSrc()).split(' ').includes(`'sha256-${sha256(IMPORTMAP)}'`));
    const page = path.join(tmp, 'site', 'web', 'index.html');
    const changed = IMPORTMAP.replace('three.module.js', 'three.module.min.js');
    fs.writeFileSync(page, PAGE.replace(IMPORTMAP, changed));
    fs.utimesSync(page, new Date(), new Date(Date.now() + 5000));
    const now = (await scriptSrc()).split(' ');
    assert.ok(now.includes(`'sha256-${sha256(changed)}'`));
    assert.ok(!now.includes(`'sha256-${sha256(IMPORTMAP)}'`));
    // The production page's boot script (scripts/build-web.mjs inlines web/boot.js), beside it.
    const app = path.join(tmp, 'site', 'build', 'web', 'index.html');
    const BOOT = '\n(() => { new Worker("./w.js"); })();\n';
    fs.writeFileSync(app, `<!doctype html><script data-worker="./w.js">${BOOT}</script><script src="./main.js"></script>`);
    fs.utimesSync(app, new Date(), new Date(Date.now() + 5000));
    const both = (await scriptSrc()).split(' ');
    assert.ok(both.includes(`'sha256-${sha256(BOOT)}'`), 'the production page\'s boot script');
    assert.ok(both.includes(`'sha256-${sha256(changed)}'`), 'and the source page\'s importmap');
    assert.equal(both.filter((s) => s.startsWith("'sha256-")).length, 2);
    // The browser hashes the text after the parser turned CR LF into LF.
    assert.deepEqual(inlineScriptHashes('<script type="importmap">{\r\n}</script><script data-a="b">x</script><script src="y.js"></script>'),
      [sha256('{\n}'), sha256('x')], 'every inline script, none with a src');
  });
});
