// Page wiring: load the solver and the example catalogue, open an example, and
// re-solve whenever the scene (the page state) changes.
import { loadSolver } from './solver/pdesurf-solver.js';
import { createViewer } from './viewer/viewer.js';
import { createPanel } from './ui/panel.js';
import { createStatus } from './ui/status.js';
import { createSceneState } from './state/scene-state.js';
import { createSolveScheduler } from './state/solve-scheduler.js';
import { loadExampleIndex, loadExampleScene } from './state/examples.js';
import { exampleIdFromHash, writeExampleIdToHash } from './state/hash.js';
import { installTestHooks } from './test-hooks.js';

const status = createStatus(document.getElementById('status'));
const titleEl = document.getElementById('scene-title');
let viewer = null;
const hooks = installTestHooks(() => (viewer ? viewer.positionArrays() : []));

function messageOf(err) {
  if (err && err.code) return `${err.code}: ${err.message}`;
  return err && err.message ? err.message : String(err);
}

// Shown in the status line; the surfaces already drawn stay as they are.
function fail(err) {
  const msg = messageOf(err);
  hooks.lastError = msg;
  status.error(msg);
}

async function start() {
  try {
    viewer = createViewer(document.getElementById('viewport'));
  } catch (err) {
    fail(new Error(`cannot start WebGL: ${err.message}`));
    return;
  }
  let solver, examples;
  try {
    [solver, examples] = await Promise.all([loadSolver(), loadExampleIndex()]);
  } catch (err) {
    fail(err);
    return;
  }

  const state = createSceneState();
  const scheduler = createSolveScheduler(solveNow);
  let fitPending = false; // frame the camera on the first good solve of an example
  let notice = null; // shown instead of the solve summary once (e.g. a bad link)
  let loadToken = 0; // a slower fetch of an earlier pick must not win

  const panel = createPanel({
    examples,
    grid: state.grid,
    onExample: (id) => openExample(id),
    onGridChange: () => scheduler.request(),
    onParameterChange: () => scheduler.request(),
    operatorHandlers: {
      methodOf: (patch) => state.methodOf(patch),
      onParam: (patch, axis, name, value) => {
        state.setOperatorParam(patch, axis, name, value);
        scheduler.request();
      },
      onOrder: (patch, axis, order) => {
        const params = state.setOperatorOrder(patch, axis, order);
        if (params) scheduler.request();
        return params;
      },
      onMethod: (patch, method) => {
        state.setMethod(patch, method);
        scheduler.request();
      },
    },
  });

  async function openExample(id) {
    let entry = examples.find((e) => e.id === id);
    if (!entry) {
      notice = `unknown example "${id}"; opened "${examples[0].title}" instead`;
      entry = examples[0];
    }
    const token = ++loadToken;
    status.info(`loading ${entry.title}…`);
    let scene;
    try {
      scene = await loadExampleScene(entry);
    } catch (err) {
      if (token === loadToken) fail(err);
      return;
    }
    if (token !== loadToken) return;
    state.setScene(scene, entry.id);
    hooks.exampleId = entry.id;
    writeExampleIdToHash(entry.id);
    panel.setExample(entry.id);
    panel.showScene(scene);
    const src = entry.source ? [entry.source.paper, entry.source.figure].filter(Boolean).join(', ') : '';
    titleEl.textContent = src ? `${entry.title} (${src})` : entry.title;
    fitPending = true;
    scheduler.request();
  }

  function solveNow() {
    if (!state.scene) return;
    hooks.solveCount++;
    const t0 = performance.now();
    let result;
    try {
      result = solver.solve(state.text(), state.grid);
    } catch (err) {
      fail(err);
      return;
    }
    const ms = performance.now() - t0;
    viewer.setPatches(result.patches);
    if (fitPending) {
      viewer.fit();
      fitPending = false;
    }
    panel.showSolved(result.patches);
    hooks.lastError = null;
    hooks.ready = true;
    const { nu, nv } = state.grid;
    const summary = `${result.patches.length} patches, grid ${nu}×${nv}, solved in ${ms.toFixed(1)} ms`;
    if (notice) status.error(notice);
    else status.info(summary);
    notice = null;
  }

  // A link edited by hand or history navigation opens the example it names.
  window.addEventListener('hashchange', () => {
    const id = exampleIdFromHash();
    if (id && id !== state.exampleId) openExample(id);
  });

  await openExample(exampleIdFromHash() || examples[0].id);
}

start().catch(fail);
