#!/usr/bin/env node
// Tiny static server for the pdesurf modeller: serves only what the page needs (the
// production build build/web/ as /app/, the sources web/ as /web/, examples/,
// node_modules/three/, /pako/, /rhino3dm/, /@jscadui/3mf-export/ and /fflate/, and as /wasm/ the .js and .wasm files of
// build/wasm/ or $PDESURF_WASM_DIR), every response with security headers (a CSP that allows
// no inline script but the importmap, and eval only in the .3dm writer's worker), compressed
// when the client accepts it (lib/encoded-body.mjs), with an ETag.
// No dependencies, so it runs on a fresh checkout.
//   node scripts/static-server.mjs [--port 8000] [--host 127.0.0.1]
import crypto from 'node:crypto';
import http from 'node:http';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { encodedBody } from './lib/encoded-body.mjs';

const REPO_ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');

const MIME = {
  '.wasm': 'application/wasm',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.html': 'text/html; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.png': 'image/png',
  '.svg': 'image/svg+xml',
  '.md': 'text/plain; charset=utf-8',
  '.stl': 'model/stl',
};

// Plain text always: a missing .wasm answered with HTML gives "magic number" errors.
function sendText(res, status, text, extraHeaders = {}) {
  res.writeHead(status, {
    'Content-Type': 'text/plain; charset=utf-8',
    'Cache-Control': 'no-store',
    ...extraHeaders,
  });
  res.end(text + '\n');
}

// The only trees served, as URL segments -> the same path under the root: the page, the
// examples it fetches, the docs its help links, and the npm packages it loads (pako: the
// link decoder; rhino3dm: the .3dm writer and reader, web/cad/rhino3dm-url.js; Open CASCADE's
// wasm build: the STEP reader, web/cad/occt-url.js; @jscadui/3mf-export and
// fflate: the 3MF writer and its zip), and the benchmark's
// bare three.js page (bench/pages/, scripts/bench-page.mjs).
const TREES = [['web'], ['examples'], ['docs'], ['node_modules', 'three'], ['node_modules', 'pako'], ['node_modules', 'rhino3dm'],
  ['node_modules', 'replicad-opencascadejs', 'dist'],
  ['node_modules', '@jscadui', '3mf-export'], ['node_modules', 'fflate'], ['bench', 'pages']];
// /wasm/<name> comes from the wasm build dir, which also holds CMake files and a symlink
// to system headers: only its top-level .js and .wasm files.
const WASM_FILE = /^[^./\\][^/\\]*\.(js|wasm)$/;

// No 'unsafe-eval': the wasm module is linked with -sDYNAMIC_EXECUTION=0, so embind builds
// its invokers without new Function. lil-gui injects its stylesheet as a <style> element,
// hence 'unsafe-inline' for styles only (styles cannot run script), and that stylesheet
// embeds its icon font as a data: URL. The inline scripts (the source page's importmap, the
// production page's boot script) are allowed by their hashes, nothing else inline.
function contentSecurityPolicy(inlineHashes) {
  const hashes = inlineHashes.map((h) => `'sha256-${h}'`);
  return [
    "default-src 'self'", ["script-src 'self' 'wasm-unsafe-eval'", ...hashes].join(' '),
    "style-src 'self' 'unsafe-inline'", "font-src 'self' data:", "img-src 'self' data: blob:",
    "connect-src 'self'", "worker-src 'self' blob:", "object-src 'none'",
    "base-uri 'none'", "frame-ancestors 'none'", "form-action 'none'",
  ].join('; ');
}

// The .3dm writer's worker (web/cad/rhino-worker.js, bundled as /app/rhino-worker.js) runs
// rhino3dm, whose embind glue needs eval; so does Open CASCADE's in the STEP reader's worker
// (web/cad/occt-worker.js, /app/occt-worker.js). A worker takes the policy sent with its own script,
// so eval is allowed there only: no DOM, no inline script, the same origin for the rest.
const EVAL_WORKERS = new Set(['/web/cad/rhino-worker.js', '/app/rhino-worker.js', '/web/cad/occt-worker.js', '/app/occt-worker.js']);
const EVAL_WORKER_POLICY = [
  "default-src 'self'", "script-src 'self' 'wasm-unsafe-eval' 'unsafe-eval'", "connect-src 'self'",
  "object-src 'none'", "base-uri 'none'",
].join('; ');

// sha256 (base64) of each inline script in `html` (an importmap, the production page's boot
// script), as the browser hashes it: the text between the tags with newlines normalised to
// LF (the HTML parser does that first).
export function inlineScriptHashes(html) {
  const re = /<script\b(?![^>]*\bsrc\s*=)[^>]*>([\s\S]*?)<\/script\s*>/gi;
  return [...html.matchAll(re)].map((m) =>
    crypto.createHash('sha256').update(m[1].replace(/\r\n?/g, '\n'), 'utf8').digest('base64'));
}

// The headers of every response, re-read when a page changes (web/index.html, the
// production build's index.html) so an edited inline script keeps its hash without a restart.
function securityHeaders(root, appDir) {
  const pages = [path.join(root, 'web', 'index.html'), path.join(appDir, 'index.html')];
  let stamp = null;
  let headers = null;
  return () => {
    const mtimes = pages.map((p) => fs.statSync(p, { throwIfNoEntry: false })?.mtimeMs ?? -1);
    if (headers && mtimes.join() === stamp) return headers;
    const hashes = pages.flatMap((p, k) => (mtimes[k] < 0 ? [] : inlineScriptHashes(fs.readFileSync(p, 'utf8'))));
    stamp = mtimes.join();
    headers = {
      'Content-Security-Policy': contentSecurityPolicy([...new Set(hashes)]),
      'X-Content-Type-Options': 'nosniff',
      'Referrer-Policy': 'no-referrer',
      'Cross-Origin-Opener-Policy': 'same-origin',
      'Cross-Origin-Resource-Policy': 'same-origin',
    };
    return headers;
  };
}

// The allowed directory and the path below it for a URL path, or null when nothing is
// served there. Segments starting with '.' (dotfiles, .git, ..) never are.
function mapPath(urlPath, root, wasmDir, appDir) {
  const segs = urlPath.split('/').slice(1);
  if (segs.some((s) => s.startsWith('.'))) return null;
  if (segs[0] === 'app') return { base: appDir, rest: segs.slice(1), dirs: true };
  if (segs[0] === 'wasm') {
    return segs.length === 2 && WASM_FILE.test(segs[1]) ? { base: wasmDir, rest: [segs[1]], dirs: false } : null;
  }
  const tree = TREES.find((t) => t.every((s, i) => segs[i] === s));
  return tree ? { base: path.join(root, ...tree), rest: segs.slice(tree.length), dirs: true } : null;
}

// The real path and stat of `file`, or null unless it is inside the real `base`
// (so a symlink may not lead out of its tree).
async function inside(base, file) {
  try {
    const [realBase, real] = await Promise.all([fs.promises.realpath(base), fs.promises.realpath(file)]);
    if (real !== realBase && !real.startsWith(realBase + path.sep)) return null;
    return { real, st: await fs.promises.stat(real) };
  } catch {
    return null;
  }
}

function handler(root, wasmDir, appDir) {
  const security = securityHeaders(root, appDir);
  return (req, res) => {
    for (const [k, v] of Object.entries(security())) res.setHeader(k, v);
    serve(req, res, root, wasmDir, appDir).catch(() => {
      if (res.headersSent) res.destroy();
      else sendText(res, 500, 'internal error');
    });
  };
}

async function serve(req, res, root, wasmDir, appDir) {
  if (req.method !== 'GET' && req.method !== 'HEAD') {
    sendText(res, 405, 'method not allowed', { Allow: 'GET, HEAD' });
    return;
  }
  let urlPath, rawPath;
  try {
    rawPath = new URL(req.url, 'http://localhost').pathname;
    urlPath = decodeURIComponent(rawPath);
  } catch {
    sendText(res, 400, 'bad request');
    return;
  }
  if (urlPath === '/') {
    // The production build when there is one (scripts/build-web.mjs), else the sources.
    const home = fs.existsSync(path.join(appDir, 'index.html')) ? '/app/' : '/web/';
    res.writeHead(302, { Location: home, 'Content-Type': 'text/plain; charset=utf-8' });
    res.end(`see ${home}\n`);
    return;
  }
  // Reject NUL and ".." segments outright (also when encoded), before any normalisation.
  if (urlPath.includes('\0') || urlPath.split(/[\\/]/).includes('..')) {
    sendText(res, 403, 'forbidden');
    return;
  }
  if (EVAL_WORKERS.has(urlPath)) res.setHeader('Content-Security-Policy', EVAL_WORKER_POLICY);
  const mapped = mapPath(urlPath, root, wasmDir, appDir);
  let found = mapped && (await inside(mapped.base, path.join(mapped.base, ...mapped.rest)));
  if (found?.st.isDirectory() && mapped.dirs) {
    // Directories need a trailing slash so relative URLs in index.html resolve.
    if (!urlPath.endsWith('/')) {
      res.writeHead(301, { Location: rawPath + '/', 'Content-Type': 'text/plain; charset=utf-8' });
      res.end('moved\n');
      return;
    }
    found = await inside(mapped.base, path.join(found.real, 'index.html'));
  }
  if (!found || !found.st.isFile()) {
    sendText(res, 404, `not found: ${urlPath}`);
    return;
  }
  const ext = path.extname(found.real).toLowerCase();
  const body = await encodedBody(req, found.real, found.st, ext);
  // Revalidated on every load (no-cache) but cheaply: an unchanged file is a 304. One tag per
  // encoding, as the response varies by it.
  const etag = `"${found.st.size.toString(36)}-${Math.floor(found.st.mtimeMs).toString(36)}${body.encoding ? `-${body.encoding}` : ''}"`;
  if (req.headers['if-none-match'] === etag) {
    res.writeHead(304, { ETag: etag, 'Cache-Control': 'no-cache', Vary: 'Accept-Encoding' });
    res.end();
    return;
  }
  res.writeHead(200, {
    'Content-Type': MIME[ext] || 'application/octet-stream',
    'Content-Length': body.size,
    ...(body.encoding ? { 'Content-Encoding': body.encoding } : {}),
    Vary: 'Accept-Encoding',
    ETag: etag,
    'Cache-Control': 'no-cache',
  });
  if (req.method === 'HEAD' || body.size === 0) {
    res.end();
    return;
  }
  // No more than Content-Length, even when the file grows while it is read (an editor saving).
  const stream = body.open();
  stream.on('error', () => res.destroy());
  stream.pipe(res);
}

/**
 * Start the server. Resolves to the listening http.Server (port 0 = ephemeral;
 * read the real port from server.address().port).
 */
export function startServer({
  port = 8000,
  host = '127.0.0.1',
  root = REPO_ROOT,
  wasmDir = process.env.PDESURF_WASM_DIR || path.join(root, 'build', 'wasm'),
  appDir = process.env.PDESURF_APP_DIR || path.join(root, 'build', 'web'),
} = {}) {
  const rootAbs = path.resolve(root);
  const wasmAbs = path.resolve(wasmDir);
  const server = http.createServer(handler(rootAbs, wasmAbs, path.resolve(appDir)));
  return new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(port, host, () => {
      server.off('error', reject);
      resolve(server);
    });
  });
}

function parseArgs(argv) {
  const opts = { port: 8000, host: '127.0.0.1' };
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    if (a === '--port') opts.port = Number(argv[++i]);
    else if (a === '--host') opts.host = argv[++i];
    else if (a === '--help' || a === '-h') {
      console.log('usage: node scripts/static-server.mjs [--port 8000] [--host 127.0.0.1]');
      process.exit(0);
    } else {
      console.error(`unknown argument: ${a}`);
      process.exit(2);
    }
  }
  if (!Number.isInteger(opts.port) || opts.port < 0 || opts.port > 65535) {
    console.error('--port needs an integer in 0..65535');
    process.exit(2);
  }
  return opts;
}

// Run as a program (not when imported by tests).
if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const opts = parseArgs(process.argv.slice(2));
  startServer(opts).then(
    (server) => console.log(`pdesurf modeller: http://localhost:${server.address().port}/`),
    (err) => {
      console.error(`cannot listen on ${opts.host}:${opts.port}: ${err.message}`);
      process.exit(1);
    },
  );
}
