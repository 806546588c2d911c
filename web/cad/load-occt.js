// Open CASCADE in wasm (replicad's build of opencascade.js) loaded on first use, once: imported
// and started when the first STEP file is opened, never at page load. Its 23 MB of wasm are
// fetched here, not by the glue, so the page can show how much has come (onProgress).
import { OCCT_URL } from './occt-url.js';
import { OCCT_WASM_BYTES } from './occt-wasm-size.js';

let started = null;
const listeners = new Set(); // onProgress(loaded, total) of every caller waiting for the first load

/**
 * The started module (a promise shared by every caller; a failure may be retried).
 * onProgress(loadedBytes, totalBytes): told as the wasm arrives (the first load only).
 */
export function loadOcct({ onProgress = null } = {}) {
  if (onProgress) listeners.add(onProgress);
  started ??= (async () => {
    const mod = await import(OCCT_URL);
    const wasmBinary = await fetchWithProgress(OCCT_URL.replace(/\.js$/, '.wasm'), (loaded, total) => {
      for (const fn of listeners) fn(loaded, total);
    });
    return mod.default({ wasmBinary });
  })().catch((err) => {
    started = null;
    throw new Error(`cannot load Open CASCADE from ${OCCT_URL}: ${err?.message ?? err}`);
  });
  const done = () => onProgress && listeners.delete(onProgress);
  started.then(done, done);
  return started;
}

// The body's bytes, counted as they arrive. The total is the wasm's own size when the server
// compressed it (Content-Length is then the compressed size), else Content-Length.
async function fetchWithProgress(url, onProgress) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
  const length = Number(response.headers.get('content-length'));
  const total = response.headers.get('content-encoding') || !(length > 0) ? OCCT_WASM_BYTES : length;
  if (!response.body) return response.arrayBuffer();
  let buffer = new Uint8Array(total);
  let loaded = 0;
  const reader = response.body.getReader();
  onProgress(0, total);
  for (;;) {
    const { done, value } = await reader.read();
    if (done) break;
    if (loaded + value.length > buffer.length) { // a different build than the size says: grow
      const grown = new Uint8Array(Math.max(buffer.length * 2, loaded + value.length));
      grown.set(buffer.subarray(0, loaded));
      buffer = grown;
    }
    buffer.set(value, loaded);
    loaded += value.length;
    onProgress(loaded, Math.max(total, loaded));
  }
  return loaded === buffer.length ? buffer.buffer : buffer.buffer.slice(0, loaded); // no 23 MB copy when the size was right
}
