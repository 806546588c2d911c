// The page's side of the solver worker (solver-worker.js): one solve at a time, requests
// coalesced (only the newest waiting request runs next), results of an older scene dropped,
// and a solve that keeps a newer edit waiting too long cancelled by restarting the worker.
//
// createSolverClient({ onResult(result, job, ms), onError(error, job), onBusy(ms | null),
//                      onReport(report, job, ms) })
//   onReport: (report, job, ms, { longestSliceMs }) the join report of the result last given to onResult, when its job asked for
//             it (options.joins): that result came without it (result.reportPending) and the
//             worker certifies after drawing; a newer solve drops it. A report that failed
//             comes as { error: { code, message } }.
//   .request(job)  job: { scene (text), options, token }; a result whose token differs from
//                  the newest request's is stale and dropped (another scene was opened).
//   .busy()        true while a solve runs
//   .restarts      how many solves were cancelled (for tests)
//   .exportCad(scene (text), { format, tolerance }) -> promise of the module's exportCad
//   .modelMesh(scene (text), { nu, nv }) -> promise of the module's modelMesh (one export at a time, as CAD's)
//   .exportCad(…, …, { onProgress(done, total, patch) }): told after each patch's fit
//   .cancelExport() -> true if an export was running or waiting: it fails with code 'Cancelled'
//        (a running one by ending its worker; the next request starts a fresh one)
//                  result ({ title, tolerance, faces, text? }, plus ms: the worker's time), or
//                  an Error with the core's code. One at a time; it runs between solves, never
//                  beside one (the worker is one thread): a solve asked for meanwhile waits
//                  for it, and no waiting edit cancels it.
// A cold start's first scene may come solved unasked (solver/ahead-solve.js): the first
// request for exactly that scene and those options takes it without a round trip.
//   .onAhead(fn)   fn(message) once that result is here ({ scene, options, result, ms }: to
//                  draw before the page is wired, web/first-surface.js; the request still
//                  takes it), or fn(null) once none will come; returns a function that stops
//                  listening.
//   .certifyAhead() that result is on screen: the worker measures its join report now (it
//                  held it so as not to slow the first frame; taking the result says so too).

// A waiting edit cancels the running solve after this long, or after 1.5 times the last
// solve's time if that is longer: a scene that always takes a second still shows a result
// per second during a drag, while a solve far slower than the last (a pathological edit)
// gives way to the next edit.
import { sameSolve } from './same-solve.js';

const CANCEL_AFTER_MS = 300;
const BUSY_AFTER_MS = 100; // "solving…" only for solves one can notice

export function createSolverClient({ onResult, onError, onBusy = () => {}, onReport = () => {}, workerUrl = new URL('./solver-worker.js', import.meta.url) }) {
  let worker = null;
  let running = null; // { id, job, started }
  let waiting = null; // { job, since }
  let exporting = null; // { id, resolve, reject, onProgress }: an export (CAD or mesh) in the worker
  let exportWaiting = null; // { kind, scene, options, resolve, reject, onProgress }: one asked for during a solve
  let nextId = 1;
  let lastMs = 0;
  let latestToken = null;
  let busyTimer = 0;
  let cancelTimer = 0;
  let ahead = null; // { scene, options, result, ms }: solved before any request (one use)
  let requested = false; // a solve was asked for: a result arriving unasked after is no use
  let aheadListeners = [];
  let delivered = null; // { ids, job }: the result last given to onResult and the worker requests
  // whose report is its report ('ahead': the solve done ahead)
  let reportAhead = null; // the report of the solve done ahead, come before that solve was taken
  const client = { restarts: 0 };
  spawn(); // now: the module loads while the page sets up
  // Only the worker web/boot.js started with the page's hash solves ahead.
  let aheadExpected = Boolean(worker.solvesAhead);

  function spawn() {
    // The worker web/boot.js started while the page loaded, once, unless it failed.
    const early = globalThis.__pdesurfEarlyWorker;
    globalThis.__pdesurfEarlyWorker = undefined;
    worker = early && !early.failed ? early : new Worker(workerUrl, { type: 'module' });
    worker.solvesAhead = worker === early;
    worker.onmessage = (e) => finished(e.data);
    // A worker that fails to load (or crashes) fails its request; the next one respawns it.
    worker.onerror = (e) => {
      e.preventDefault();
      const job = running?.job;
      const error = { code: 'Load', message: `the solver worker failed: ${e.message || 'unknown error'}` };
      noneAhead();
      stopRunning();
      worker.terminate();
      worker = null;
      if (job) onError(error, job);
      if (exporting) exporting.reject(failure(error));
      exporting = null;
      next();
    };
  }

  function stopRunning() {
    running = null;
    clearInterval(busyTimer);
    busyTimer = 0;
    onBusy(null);
  }

  function dispatch(job) {
    if (!worker) spawn();
    running = { id: nextId++, job, started: performance.now() };
    worker.postMessage({ id: running.id, scene: job.scene, options: job.options });
    busyTimer = setInterval(() => {
      const ms = performance.now() - running.started;
      if (ms >= BUSY_AFTER_MS) onBusy(ms);
    }, BUSY_AFTER_MS);
  }

  function dispatchExport({ kind, scene, options, resolve, reject, onProgress }) {
    if (!worker) spawn();
    exporting = { id: nextId++, resolve, reject, onProgress };
    worker.postMessage({ id: exporting.id, kind, scene, options });
  }

  // An export asked for goes first: it is one click, where waiting solves are coalesced edits.
  function next() {
    clearTimeout(cancelTimer);
    cancelTimer = 0;
    if (running || exporting) return;
    if (exportWaiting) {
      const req = exportWaiting;
      exportWaiting = null;
      dispatchExport(req);
      return;
    }
    if (!waiting) return;
    const { job } = waiting;
    waiting = null;
    dispatch(job);
  }

  function exported(msg) {
    if (!exporting || msg.id !== exporting.id) return;
    const { resolve, reject } = exporting;
    exporting = null;
    if (msg.ok) resolve({ ...msg.result, ms: msg.ms });
    else reject(failure(msg.error));
    next();
  }

  function finished(msg) {
    if (msg.kind === 'report') {
      if (delivered && delivered.ids.includes(msg.id)) reported(msg);
      else if (msg.id === 'ahead') reportAhead = msg; // before the page took the solve ahead
      return;
    }
    if (msg.kind === 'progress') {
      if (exporting && msg.id === exporting.id) exporting.onProgress?.(msg.done, msg.total, msg.patch);
      return;
    }
    if (msg.kind === 'exportCad' || msg.kind === 'modelMesh') {
      exported(msg);
      return;
    }
    if (msg.kind === 'ahead') {
      performance.mark('pdesurf:ahead-arrived');
      arrivedAhead(msg);
      return;
    }
    if (!running || msg.id !== running.id) return;
    const { job } = running;
    lastMs = msg.ms;
    stopRunning();
    if (job.token === latestToken) {
      if (msg.ok) deliver([msg.id], msg.result, job, msg.ms);
      else onError(msg.error, job);
    }
    next();
  }

  function deliver(ids, result, job, ms) {
    delivered = { ids, job };
    onResult(result, job, ms);
    if (reportAhead && ids.includes(reportAhead.id)) reported(reportAhead);
    reportAhead = null;
  }

  function reported(msg) {
    if (delivered.job.token === latestToken) onReport(msg.ok ? msg.result : { error: msg.error }, delivered.job, msg.ms, { longestSliceMs: msg.longestSliceMs });
  }

  // A cold start's first scene, solved unasked. Kept for the first request; or the answer to
  // the running one, asked for meanwhile (the worker then solves it again: that reply is dropped).
  function arrivedAhead(msg) {
    if (!msg.result) noneAhead(); // the worker could not solve it (the request will say why)
    else if (running && sameSolve(msg, running.job)) {
      const { job, id } = running;
      stopRunning();
      // The worker solves the request again and drops the ahead's report for it: its report
      // is the one that comes.
      if (job.token === latestToken) deliver(['ahead', id], msg.result, job, msg.ms);
      next();
    } else if (!requested) {
      ahead = msg;
      const listeners = aheadListeners;
      aheadListeners = [];
      for (const fn of listeners) fn(msg);
    }
  }

  function noneAhead() {
    aheadExpected = false;
    const listeners = aheadListeners;
    aheadListeners = [];
    for (const fn of listeners) fn(null);
  }

  // The running solve has kept a newer request waiting past the limit: drop the worker (and
  // its caches: a terminated worker cannot be interrupted any other way) and start afresh.
  function cancelIfStuck() {
    cancelTimer = 0;
    if (!running || !waiting) return;
    client.restarts++;
    worker.terminate();
    worker = null;
    stopRunning();
    next();
  }

  // The worker holds the report of its solve ahead until that surface is drawn (its work
  // would slow the first frame down): the page says so once it is on screen, or takes it.
  let aheadCertified = false;
  client.certifyAhead = () => {
    if (aheadCertified || !worker?.solvesAhead) return;
    aheadCertified = true;
    worker.postMessage({ kind: 'certifyAhead' });
  };

  client.request = (job) => {
    latestToken = job.token;
    requested = true;
    const early = ahead;
    ahead = null;
    if (early && !running && !exporting && sameSolve(early, job)) {
      client.certifyAhead();
      // After the caller's task, as a worker's reply would be (the caller may not be ready).
      queueMicrotask(() => {
        if (job.token === latestToken) deliver(['ahead'], early.result, job, early.ms);
      });
      return;
    }
    if (!running && !exporting) {
      dispatch(job);
      return;
    }
    if (!waiting) waiting = { job, since: performance.now() };
    else waiting.job = job; // coalesce: only the newest waiting request will run
    if (running && !cancelTimer) cancelTimer = setTimeout(cancelIfStuck, Math.max(CANCEL_AFTER_MS, 1.5 * lastMs));
  };
  client.onAhead = (fn) => {
    if (ahead) fn(ahead);
    else if (!aheadExpected || requested) fn(null);
    else {
      aheadListeners.push(fn);
      return () => {
        aheadListeners = aheadListeners.filter((f) => f !== fn);
      };
    }
    return () => {};
  };
  client.busy = () => running !== null;
  const exportJob = (kind) => (scene, options, { onProgress } = {}) => new Promise((resolve, reject) => {
    if (exporting || exportWaiting) {
      reject(new Error('another export is running'));
      return;
    }
    const req = { kind, scene, options, resolve, reject, onProgress };
    if (running) exportWaiting = req; // after this solve (next())
    else dispatchExport(req);
  });
  client.exportCad = exportJob('exportCad');
  client.modelMesh = exportJob('modelMesh');
  // The module cannot be interrupted inside a call: a running export ends with its worker.
  client.cancelExport = () => {
    const cancelled = Object.assign(new Error('cancelled'), { code: 'Cancelled' });
    if (exportWaiting) {
      exportWaiting.reject(cancelled);
      exportWaiting = null;
      return true;
    }
    if (!exporting) return false;
    const { reject } = exporting;
    exporting = null;
    noneAhead();
    worker.terminate();
    worker = null;
    reject(cancelled);
    next();
    return true;
  };
  return client;
}

// The worker's { code, message } as an Error (messageOf in state/document.js shows both).
function failure({ code, message }) {
  return Object.assign(new Error(message), { code });
}
