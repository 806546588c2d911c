// The solver's thread: a module Web Worker that owns the wasm module, so no solve ever runs
// on the page's main thread (web/solver/solver-client.js talks to it).
//   in:  { id, scene (JSON text), options: { nu, nv, curvature, joins, crossings } }
//   out: { id, ok: true, result, ms } with every typed array transferred (moved, not copied),
//        or { id, ok: false, error: { code, message }, ms }
// uvs and indices are never sent: they depend on the grid alone and the page builds them
// (viewer/grid-topology.js).
import { loadSolver } from './pdesurf-solver.js';

const ready = loadSolver();
ready.catch(() => {}); // reported with the first request

function transferablesOf(result) {
  const buffers = new Set();
  for (const p of result.patches)
    for (const v of Object.values(p)) if (ArrayBuffer.isView(v)) buffers.add(v.buffer);
  return [...buffers];
}

self.onmessage = async (event) => {
  const { id, scene, options } = event.data;
  const t0 = performance.now();
  try {
    const solver = await ready;
    const result = solver.solve(scene, { ...options, topology: false });
    self.postMessage({ id, ok: true, result, ms: performance.now() - t0 }, transferablesOf(result));
  } catch (err) {
    const error = { code: String(err?.code || 'Internal'), message: String(err?.message || err) };
    self.postMessage({ id, ok: false, error, ms: performance.now() - t0 });
  }
};
