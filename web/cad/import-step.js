// The page's way to read a STEP file (read-step.js in occt-worker.js, see there why): the
// worker starts on the first STEP file opened, so nothing of Open CASCADE (23 MB of wasm) is
// fetched before, and stays for the next ones. Its URL is relative: beside this file in
// web/cad/, beside the bundle's chunks in build/web/ (scripts/build-web.mjs).
let worker = null;
let nextId = 0;
const pending = new Map(); // id -> { resolve, reject }

function start() {
  worker = new Worker(new URL('./occt-worker.js', import.meta.url), { type: 'module' });
  worker.onmessage = ({ data }) => {
    const p = pending.get(data.id);
    pending.delete(data.id);
    if (data.error) p?.reject(Object.assign(new Error(data.error), { code: data.code }));
    else p?.resolve(data.scene);
  };
  // A worker that cannot load fails every request in flight; the next opening starts a new one.
  worker.onerror = (e) => {
    e.preventDefault?.();
    for (const p of pending.values()) p.reject(new Error(`Open CASCADE's worker stopped: ${e.message || 'it could not load'}`));
    pending.clear();
    worker.terminate();
    worker = null;
  };
}

/** A STEP file's bytes (an ArrayBuffer, handed over) as a scene, off the page's thread. */
export function importStep(bytes, fileName) {
  if (!worker) start();
  const id = nextId++;
  return new Promise((resolve, reject) => {
    pending.set(id, { resolve, reject });
    worker.postMessage({ id, read: bytes, fileName }, [bytes]);
  });
}
