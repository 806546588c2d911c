// The solver's thread: a module Web Worker that owns the wasm module, so no solve ever runs
// on the page's main thread (web/solver/solver-client.js talks to it).
//   in:  { id, scene (JSON text), options: { nu, nv, curvature, joins, crossings } }
//   out: { id, ok: true, result, ms } with every typed array transferred (moved, not copied),
//        or { id, ok: false, error: { code, message }, ms }
// Unasked, once, on a cold start: { kind: 'ahead', scene, options, result, ms }, the example
// the page's hash names, solved ahead (ahead-solve.js); { kind: 'ahead', result: null } if
// there is none.
// A CAD export (the File folder's STEP, IGES, 3dm; docs/wasm-api.md, exportCad):
//   in:  { id, kind: 'exportCad', scene, options: { format, tolerance } }
//   out: { id, kind: 'exportCad', ok: true, result: { title, tolerance, faces, text? }, ms }
//        with the faces' knots and poles transferred, or the same failure as a solve; before
//        it, after each patch's fit, { id, kind: 'progress', done, total, patch }
// The model's watertight mesh (the File folder's OBJ, STL, GLB, 3MF; modelMesh):
//   in:  { id, kind: 'modelMesh', scene, options: { nu, nv } }
//   out: { id, kind: 'modelMesh', ok: true, result: { title, positions, normals, parts, bodies }, ms }
// uvs and indices are never sent: they depend on the grid alone and the page builds them
// (viewer/grid-topology.js).
// A solve that asks for the join report (options.joins) is answered without it (result.
// reportPending: true) as soon as its mesh is made; the report follows, measured in slices of
// REPORT_SLICE_MS between which any message that arrived runs first:
//   out: { id, kind: 'report', ok: true, result: report, ms, measured, kept, longestSliceMs }
//        (id 'ahead' for the solve done ahead; longestSliceMs: the longest the report held the
//        worker at once, what an edit may wait behind it), or the same failure as a solve
// A new solve drops the report in progress (it is of an older scene); any other request (an
// export), or a solve that fails, pauses it: it starts again after, keeping the parts already
// measured. The report of the solve done ahead begins when the page says it has drawn it:
//   in:  { kind: 'certifyAhead' } (no reply but that report)
import { loadSolver } from './pdesurf-solver.js';
import { createAheadSolve } from './ahead-solve.js';

// The .wasm is compiled as it streams in (and a repeat visit gets the engine's code cache),
// in parallel with the glue code's import.
const ready = loadSolver({ wasmModule: compileWasm('/wasm/pdesurf.wasm') });
ready.catch(() => {}); // reported with the first request

// A small solve while the page still loads its example: the module's first calls run in
// the engine's baseline tier (a first solve took 39 ms against 1.3 ms warm). Skipped when
// the page's first request is already here: it would only make that one wait.
let asked = false;
const WARM_UP = JSON.stringify({
  format: 'pdesurf-scene', version: 2, title: 'warm-up',
  patches: [{
    name: 'w', kind: 'pde', v_range: [0, 6.283185307179586], operator: { order: 4, b: 1, c: 2, d: 1 },
    boundary: {
      x: { u0: ['cos(v)', 'cos(v)'], u1: ['0.5*cos(v)', '0'] },
      y: { u0: ['sin(v)', 'sin(v)'], u1: ['0.5*sin(v)', '0'] },
      z: { u0: ['0', '0'], u1: ['1', '1'] },
    },
  }],
});
// A task, not this promise's reaction: a request that arrived while the module compiled is
// then seen first.
ready.then((solver) => setTimeout(() => {
  if (asked) return;
  try {
    solver.solve(WARM_UP, { nu: 16, nv: 16, curvature: true, joins: true, topology: false });
  } catch {
    // only a warm-up
  }
}), () => {});

// A server that sends the .wasm with another content type than application/wasm fails
// streaming compilation: then it is compiled from its bytes.
async function compileWasm(url) {
  try {
    return await WebAssembly.compileStreaming(fetch(url));
  } catch {
    const response = await fetch(url);
    if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
    return WebAssembly.compile(await response.arrayBuffer());
  }
}

// patches of a solve, faces of a CAD export: their typed arrays' buffers.
function transferablesOf(items) {
  const buffers = new Set();
  for (const p of items)
    for (const v of Object.values(p)) if (ArrayBuffer.isView(v)) buffers.add(v.buffer);
  return [...buffers];
}

const run = {
  solve: (solver, scene, options) => {
    const result = solver.solve(scene, { ...options, joins: false, topology: false });
    if (options?.joins) result.reportPending = true;
    return [result, transferablesOf(result.patches)];
  },
  exportCad: (solver, scene, { format, tolerance }, id) => {
    // Posted from inside the module's call: the page gets each message at once.
    const onProgress = (done, total, patch) => self.postMessage({ id, kind: 'progress', done, total, patch });
    const result = solver.exportCad(scene, { format, tolerance, onProgress });
    return [result, transferablesOf(result.faces)];
  },
  modelMesh: (solver, scene, { nu, nv }) => {
    const result = solver.modelMesh(scene, { nu, nv });
    return [result, transferablesOf([result, ...result.parts])];
  },
};

// The scene a cold start will ask for first, solved as soon as the module is ready, while
// the page is still loading: web/boot.js starts this worker with the page's hash in its URL
// (#first=…; a message would wait behind the module's loading).
// Its report waits until the page has drawn it ({ kind: 'certifyAhead' }): measured at once,
// the report's calls made the engine optimise the module on the machine's other core while
// that first frame was being drawn (40 ms later on screen with two cores).
let heldAheadReport = null; // { options } of the solve ahead posted, its report not begun
const ahead = createAheadSolve(ready, run.solve, (message, transfer) => {
  self.postMessage({ kind: 'ahead', ...message }, transfer);
  if (message.result?.reportPending) heldAheadReport = { options: message.options };
});
async function certifyAhead() {
  const held = heldAheadReport;
  heldAheadReport = null;
  if (held && !reporting) certifyAfter(await ready, 'ahead', held.options);
}

// The join report of the module's last solve, after its mesh was posted: in slices, so the
// next edit (a message) runs between them instead of waiting for the whole report.
const REPORT_SLICE_MS = 8;
let reporting = null; // { id, options }: the report in progress (its slices check they still are)
// The next slice as a task of its own: a message to itself, not setTimeout (nested timeouts
// are clamped to 4 ms each: a hundred milliseconds over a report of thirty slices).
const yieldChannel = new MessageChannel();
let afterYield = null;
yieldChannel.port1.onmessage = () => {
  const run = afterYield;
  afterYield = null;
  run?.();
};
function nextTask(fn) {
  afterYield = fn;
  yieldChannel.port2.postMessage(0);
}
function certifyAfter(solver, id, options) {
  const job = { id, options, started: performance.now(), longestSliceMs: 0 };
  reporting = job;
  const slice = (first) => {
    if (reporting !== job) return; // a newer solve made it stale, or a request paused it
    const sliceStart = performance.now();
    try {
      if (first) solver.reportBegin({ crossings: Boolean(options?.crossings) });
      const r = solver.reportStep(REPORT_SLICE_MS);
      job.longestSliceMs = Math.max(job.longestSliceMs, performance.now() - sliceStart);
      if (!r.done) {
        nextTask(() => slice(false));
        return;
      }
      reporting = null;
      self.postMessage({ id, kind: 'report', ok: true, result: r.report, ms: performance.now() - job.started, measured: r.measured, kept: r.kept, longestSliceMs: job.longestSliceMs });
    } catch (err) {
      reporting = null;
      self.postMessage({ id, kind: 'report', ok: false, error: { code: String(err?.code || 'Internal'), message: String(err?.message || err) } });
    }
  };
  nextTask(() => slice(true));
}
const first = new URLSearchParams(self.location.hash.slice(1)).get('first');
if (first !== null) {
  asked = true; // the solve ahead warms the module up instead
  ahead.start(first);
}

self.onmessage = async (event) => {
  asked = true;
  const { id, kind = 'solve', scene, options } = event.data;
  if (kind === 'certifyAhead') {
    certifyAhead();
    return;
  }
  // A solve makes the report in progress stale; anything else pauses it (resumed below), and
  // so does a solve that fails: the module's last solve is still the one drawn.
  const paused = reporting;
  reporting = null;
  let solved = false;
  const t0 = performance.now();
  try {
    const early = kind === 'solve' ? await ahead.take(scene, options) : null;
    if (early) {
      self.postMessage({ id, kind, ok: true, result: early.result, ms: early.ms }, early.transfer);
      if (early.result.reportPending) certifyAfter(await ready, id, options);
      return;
    }
    const solver = await ready;
    if (!Object.hasOwn(run, kind)) throw new Error(`unknown request ${JSON.stringify(kind)}`);
    const [result, transfer] = run[kind](solver, scene, options, id);
    self.postMessage({ id, kind, ok: true, result, ms: performance.now() - t0 }, transfer);
    solved = kind === 'solve';
    if (solved) heldAheadReport = null; // the module's last solve is no longer the one ahead
    if (solved && result.reportPending) certifyAfter(solver, id, options);
  } catch (err) {
    const error = { code: String(err?.code || 'Internal'), message: String(err?.message || err) };
    self.postMessage({ id, kind, ok: false, error, ms: performance.now() - t0 });
  }
  // The module's last solve is still the paused report's (exports solve on their own): again,
  // from its first part (the parts measured are kept).
  if (paused && !solved && !reporting) certifyAfter(await ready, paused.id, paused.options);
};
