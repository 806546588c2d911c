#!/usr/bin/env node
// Tiny static server for the pdesurf modeller: serves the repo root, maps /wasm/ to
// build/wasm/ (or $PDESURF_WASM_DIR). No dependencies, so it runs on a fresh checkout.
//   node scripts/static-server.mjs [--port 8000] [--host 127.0.0.1]
import http from 'node:http';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

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

// Resolve `rel` under `base`; null when it would escape `base`.
function safeJoin(base, rel) {
  const full = path.resolve(base, '.' + path.posix.sep + rel);
  const baseWithSep = base.endsWith(path.sep) ? base : base + path.sep;
  if (full !== base && !full.startsWith(baseWithSep)) return null;
  return full;
}

// Map a decoded URL path to a file on disk, or null for a traversal attempt.
function resolvePath(urlPath, root, wasmDir) {
  if (urlPath.includes('\0')) return null;
  // Reject ".." segments outright (also when encoded), before any normalisation.
  if (urlPath.split(/[\\/]/).includes('..')) return null;
  if (urlPath.startsWith('/wasm/')) return safeJoin(wasmDir, urlPath.slice('/wasm/'.length));
  return safeJoin(root, urlPath.slice(1));
}

function handler(root, wasmDir) {
  return (req, res) => {
    if (req.method !== 'GET' && req.method !== 'HEAD') {
      sendText(res, 405, 'method not allowed', { Allow: 'GET, HEAD' });
      return;
    }
    let urlPath;
    try {
      urlPath = decodeURIComponent(new URL(req.url, 'http://localhost').pathname);
    } catch {
      sendText(res, 400, 'bad request');
      return;
    }
    if (urlPath === '/') {
      res.writeHead(302, { Location: '/web/', 'Content-Type': 'text/plain; charset=utf-8' });
      res.end('see /web/\n');
      return;
    }
    let file = resolvePath(urlPath, root, wasmDir);
    if (!file) {
      sendText(res, 403, 'forbidden');
      return;
    }
    fs.stat(file, (err, st) => {
      if (!err && st.isDirectory()) {
        // Directories need a trailing slash so relative URLs in index.html resolve.
        if (!urlPath.endsWith('/')) {
          res.writeHead(301, { Location: urlPath + '/', 'Content-Type': 'text/plain; charset=utf-8' });
          res.end('moved\n');
          return;
        }
        file = path.join(file, 'index.html');
        st = fs.existsSync(file) ? fs.statSync(file) : null;
      }
      if (err || !st || !st.isFile()) {
        sendText(res, 404, `not found: ${urlPath}`);
        return;
      }
      const type = MIME[path.extname(file).toLowerCase()] || 'application/octet-stream';
      res.writeHead(200, {
        'Content-Type': type,
        'Content-Length': st.size,
        // Development server: always serve the freshly built wasm and sources.
        'Cache-Control': 'no-cache',
      });
      if (req.method === 'HEAD') {
        res.end();
        return;
      }
      const stream = fs.createReadStream(file);
      stream.on('error', () => res.destroy());
      stream.pipe(res);
    });
  };
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
} = {}) {
  const rootAbs = path.resolve(root);
  const wasmAbs = path.resolve(wasmDir);
  const server = http.createServer(handler(rootAbs, wasmAbs));
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
