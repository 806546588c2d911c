// The static server the modeller and the browser tests run on: MIME types the
// browser insists on, plain-text 404s, the /wasm/ mapping, and no path traversal.
import { describe, it, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import { startServer } from '../../scripts/static-server.mjs';

// Raw request, so "../" reaches the server un-normalised (fetch would clean it up).
function get(port, rawPath) {
  return new Promise((resolve, reject) => {
    const req = http.request({ host: '127.0.0.1', port, path: rawPath, method: 'GET' }, (res) => {
      let body = '';
      res.setEncoding('utf8');
      res.on('data', (c) => (body += c));
      res.on('end', () => resolve({ status: res.statusCode, headers: res.headers, body }));
    });
    req.on('error', reject);
    req.end();
  });
}

describe('static server', () => {
  let server, port, tmp;

  before(async () => {
    tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'pdesurf-server-'));
    const root = path.join(tmp, 'site');
    const wasm = path.join(tmp, 'wasm-out');
    fs.mkdirSync(path.join(root, 'web'), { recursive: true });
    fs.mkdirSync(wasm);
    fs.writeFileSync(path.join(root, 'web', 'index.html'), '<!doctype html><title>t</title>');
    fs.writeFileSync(path.join(root, 'web', 'a.js'), 'export {};');
    fs.writeFileSync(path.join(root, 'data.json'), '{}');
    fs.writeFileSync(path.join(wasm, 'pdesurf.wasm'), Buffer.from([0, 0x61, 0x73, 0x6d, 1, 0, 0, 0]));
    fs.writeFileSync(path.join(tmp, 'secret.txt'), 'outside the root');
    server = await startServer({ port: 0, root, wasmDir: wasm });
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
    assert.match((await get(port, '/data.json')).headers['content-type'], /^application\/json/);
    const w = await get(port, '/wasm/pdesurf.wasm');
    assert.equal(w.status, 200);
    assert.equal(w.headers['content-type'], 'application/wasm');
  });

  it('answers a missing file with a plain-text 404', async () => {
    for (const p of ['/nope.js', '/wasm/pdesurf.js', '/web/missing/']) {
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
});
