// A worker started on the first request and kept for the next ones (the CAD libraries' workers:
// rhino-worker.js, occt-worker.js). Requests carry an id; the worker answers { id, error, code }
// or { id, ...result }, and any number of { id, progress } before it (given to the request's
// onProgress). A worker that cannot load (a missing file, a refused script) fails
// every request in flight; the next request starts a new one.
/**
 * make() -> a new Worker; label names it in errors. Returns request(message, transfer,
 * { onProgress }) -> a promise of the answer.
 */
export function createWorkerClient(make, label) {
  let worker = null;
  let nextId = 0;
  const pending = new Map(); // id -> { resolve, reject, onProgress }

  function start() {
    worker = make();
    worker.onmessage = ({ data }) => {
      const p = pending.get(data.id);
      if (data.progress) {
        p?.onProgress?.(data.progress);
        return;
      }
      pending.delete(data.id);
      if (data.error) p?.reject(Object.assign(new Error(data.error), { code: data.code }));
      else p?.resolve(data);
    };
    worker.onerror = (e) => {
      e.preventDefault?.();
      for (const p of pending.values()) p.reject(new Error(`${label} stopped: ${e.message || 'it could not load'}`));
      pending.clear();
      worker.terminate();
      worker = null;
    };
  }

  return function request(message, transfer = [], { onProgress = null } = {}) {
    if (!worker) start();
    const id = nextId++;
    return new Promise((resolve, reject) => {
      pending.set(id, { resolve, reject, onProgress });
      worker.postMessage({ ...message, id }, transfer);
    });
  };
}
