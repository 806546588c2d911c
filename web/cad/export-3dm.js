// The page's way to write and to read a .3dm file (write-3dm.js and read-3dm.js in
// rhino-worker.js, see there why): the worker starts on the first .3dm export or opening, so
// nothing of rhino3dm is fetched before, and stays for the next ones. The worker's URL is relative: beside this file in web/cad/, beside the
// bundle's chunks in build/web/ (scripts/build-web.mjs).
let worker = null;
let nextId = 0;
const pending = new Map(); // id -> { resolve, reject }

function start() {
  worker = new Worker(new URL('./rhino-worker.js', import.meta.url), { type: 'module' });
  worker.onmessage = ({ data }) => {
    const p = pending.get(data.id);
    pending.delete(data.id);
    if (data.error) p?.reject(Object.assign(new Error(data.error), { code: data.code }));
    else p?.resolve(data.scene ?? data.bytes);
  };
  // A worker that cannot load (a missing file, a refused script) fails every request in
  // flight; the next export starts a new one.
  worker.onerror = (e) => {
    e.preventDefault?.();
    for (const p of pending.values()) p.reject(new Error(`rhino3dm's worker stopped: ${e.message || 'it could not load'}`));
    pending.clear();
    worker.terminate();
    worker = null;
  };
}

/** The bytes of a .3dm file of `surfaces` joined as `breps` (write-3dm.js's write3dm, off the page's thread). */
export function export3dm(surfaces, { tolerance, title, breps, archive } = {}) {
  if (!worker) start();
  const id = nextId++;
  return new Promise((resolve, reject) => {
    pending.set(id, { resolve, reject });
    worker.postMessage({ id, surfaces, tolerance, title, breps, archive });
  });
}

/** A .3dm file's bytes (an ArrayBuffer, handed over) as a scene (read-3dm.js's read3dm, off the page's thread). */
export function import3dm(bytes, fileName) {
  if (!worker) start();
  const id = nextId++;
  return new Promise((resolve, reject) => {
    pending.set(id, { resolve, reject });
    worker.postMessage({ id, read: bytes, fileName }, [bytes]);
  });
}
