// Page wiring: load the solver and the example catalogue, open what the URL hash
// names (a shared link, an example, or the default example), and re-solve whenever
// the scene (the page state) changes.
import { createSolverClient } from './solver/solver-client.js';
import { gridTopology } from './viewer/grid-topology.js';
import { createViewer } from './viewer/viewer.js';
import { createPanelWiring } from './panel-wiring.js';
import { createDocument } from './state/document.js';
import { subscribeToEdits } from './edit-subscribers.js';
import { createGallery } from './ui/gallery.js';
import { createStatus } from './ui/status.js';
import { createToolbar } from './ui/toolbar.js';
import { createLayout } from './ui/layout.js';
import { createHelpOverlay } from './ui/help-overlay.js';
import { watchNumberControls } from './ui/number-access.js';
import { installShortcuts } from './keyboard-shortcuts.js';
import { createSceneState, DEFAULT_GRID } from './state/scene-state.js';
import { createSolveScheduler } from './state/solve-scheduler.js';
import { loadExampleIndex, loadExampleScene } from './state/examples.js';
import { readHash, writeExampleIdToHash, markHashShown, hashIsShown } from './state/hash.js';
import { decodeFragment } from './link/link-codec.js';
import { installTestHooks } from './test-hooks.js';
import { createBezierWiring } from './bezier-wiring.js';
import { createShareWiring } from './share-wiring.js';
import { createAnalysisWiring } from './analysis-wiring.js';
import { createFileWiring } from './file-wiring.js';
import { createHistoryWiring } from './history-wiring.js';
import { createBuildWiring } from './build-wiring.js';

const status = createStatus(document.getElementById('status'));
const titleEl = document.getElementById('scene-title');
const toolbar = createToolbar(document.getElementById('toolbar'));
const layout = createLayout();
const help = createHelpOverlay();
let viewer = null;
let analysis = null;
const bezier = createBezierWiring();
const hooks = installTestHooks(() => (viewer ? viewer.positionArrays() : []), () => viewer?.getCamera() ?? null, {
  overlays: () => viewer?.overlayCounts() ?? null,
  editing: () => viewer?.editor.active() ?? null,
  controlPointScreen: (patch, i, j) => viewer.screenOf(bezier.pointOf(patch, i, j)),
  analysis: () => analysis?.state() ?? null,
  cameraState: () => viewer?.cameraState() ?? null,
  patchCurvature: (name) => analysis?.patchCurvature(name) ?? null,
  vertexScreen: (patch, k) => viewer.vertexScreen(patch, k),
  vertexWorld: (patch, k) => viewer.vertexWorld(patch, k),
  screenOf: (xyz) => viewer.screenOf(xyz),
  // The viewer's modeller tools (border picker, placement gizmo, marks), for their tests.
  modeller: () => viewer && { borders: viewer.borders, placement: viewer.placement, meshOf: viewer.meshOf,
    select: viewer.select, setPatchVisible: viewer.setPatchVisible, marks: viewer.marks },
});

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
  // The wasm module lives in a worker (solver/solver-worker.js): no solve on this thread.
  // Started first, so the module loads while the view and the examples do.
  let applyResult = () => {};
  let applyFailure = () => {};
  const solver = createSolverClient({
    onResult: (result, job, ms) => applyResult(result, job, ms),
    onError: (err, job) => applyFailure(err, job),
    onBusy: (ms) => status.busy(ms),
  });
  hooks.solverRestarts = () => solver.restarts;
  // For scripts/bench-page.mjs: a grid past the panel's 256 (the page path at 1024²).
  hooks.requestGrid = (nu, nv) => {
    Object.assign(state.grid, { nu, nv });
    scheduler.request();
  };
  try {
    viewer = createViewer(document.getElementById('viewport'), bezier.viewerHandlers);
  } catch (err) {
    fail(new Error(`cannot start WebGL: ${err.message}`));
    return;
  }
  let examples;
  try {
    examples = await loadExampleIndex();
  } catch (err) {
    fail(err);
    return;
  }
  let sceneToken = 0; // a new scene (example or link): results for an older one are dropped

  const state = createSceneState();
  hooks.sceneText = () => state.text();
  const scheduler = createSolveScheduler(solveNow);
  let fitPending = false; // frame the camera on the first good solve of an example
  let cameraPending = null; // or restore a shared link's camera instead
  let linkPending = false; // a link's scene that has not solved yet
  let opening = false; // the next solve opens a scene (not a user's change)
  let notice = null; // shown instead of the solve summary once (e.g. a bad link)
  let loadToken = 0; // a slower fetch or decode of an earlier pick must not win

  const gallery = createGallery(document.getElementById('gallery'), examples, (id) => openExample(id), layout);
  const doc = createDocument(state);
  let share = null;
  const panel = createPanelWiring({ doc, share: () => share, bezier });
  subscribeToEdits(doc, { panel, status, scheduler });

  watchNumberControls(panel.gui);
  // At small sizes the panel is a sheet: its title bar closes it rather than folding it.
  panel.gui.$title.addEventListener('click', () => {
    if (panel.gui._closed && layout.isCompact()) {
      panel.gui.open();
      layout.showPanel(false);
    }
  });
  const undoRedo = createHistoryWiring({
    hooks, restore: restoreScene, camera: () => viewer.getCamera(),
    read: () => ({ sceneText: state.text(), grid: { ...state.grid }, exampleId: state.exampleId, title: titleEl.textContent }),
  });
  addToolbarButtons();
  // An edit the solver judges is a step only once it is kept.
  doc.on('judging', () => undoRedo.hold());
  doc.on('judged', (kept) => undoRedo.release(kept));
  installShortcuts({ fit: () => viewer.fit(true), help, layout });

  bezier.connect({ state, viewer, panel, doc, status });
  share = createShareWiring({ viewer, panel, status, hooks });
  const files = createFileWiring({ panel, viewer, state, status, hooks, showScene,
    currentTitle: () => titleEl.textContent, setNotice: (text) => { notice = text; } });
  const building = createBuildWiring({ doc, panel, viewer, hooks, openBuilt: (scene, title) => {
    showScene(scene, { title });
    opening = false; // a built scene is the user's: its link is written at its first solve
  } });
  let quiet = false; // the next solve only adds analysis data: not a user's edit
  analysis = createAnalysisWiring({
    panel, viewer, hasAnalysis: true,
    requestSolve: () => {
      quiet = true;
      scheduler.request();
    },
  });

  // Another scene on screen: fresh overlays, analysis and panel, its gallery entry and title,
  // and the camera it comes with (else framed on its first solve).
  function presentScene(scene, exampleId, title, camera) {
    viewer.resetOverlays();
    bezier.reset();
    analysis.newScene();
    panel.showScene(scene);
    gallery.setActive(exampleId, typeof scene.description === 'string' ? scene.description : '');
    titleEl.textContent = title;
    cameraPending = camera;
    fitPending = !camera;
    building.sceneShown();
  }

  // Shared by examples and links: the scene becomes the page state and is solved.
  function showScene(scene, { exampleId = null, title, camera = null }) {
    sceneToken++;
    share.opening();
    opening = true;
    state.setScene(scene, exampleId);
    doc.reset();
    hooks.exampleId = exampleId;
    presentScene(scene, exampleId, title, camera);
    scheduler.request();
    undoRedo.opened();
    return sceneToken;
  }

  // An undo or redo: the snapshot's scene, grid and title come back and re-solve as an edit
  // (the hash follows). The camera stays within a scene; another scene comes back with the
  // view it was left with (`camera`), or framed.
  function restoreScene({ sceneText, grid, exampleId, title }, camera) {
    const scene = JSON.parse(sceneText);
    const sameScene = exampleId === state.exampleId && title === titleEl.textContent;
    sceneToken++;
    loadToken++; // an example still loading would open over the restored state
    opening = linkPending = fitPending = false;
    cameraPending = null;
    state.setScene(scene, exampleId);
    doc.reset();
    Object.assign(state.grid, grid);
    panel.refreshGrid();
    hooks.exampleId = exampleId;
    if (sameScene) {
      panel.restoreScene(scene); // overlays and the edited point stay
      building.sceneShown();
    } else presentScene(scene, exampleId, title, camera);
    scheduler.request();
  }

  function addToolbarButtons() {
    toolbar.add({ action: 'gallery', label: '☰ Examples', title: 'Examples', group: 'layout', onClick: () => layout.toggleGallery() });
    toolbar.add({ action: 'panel', label: '⚙ Controls', title: 'Controls', group: 'layout', onClick: () => layout.togglePanel() });
    undoRedo.addButtons(toolbar);
    toolbar.add({ action: 'fit', label: '⤢', title: 'Fit the view to every patch (F)', group: 'view', onClick: () => viewer.fit(true) });
    toolbar.add({ action: 'help', label: '?', title: 'Keys, gestures and docs (?)', group: 'help', onClick: () => help.toggle() });
    const mark = () => {
      toolbar.button('gallery').setAttribute('aria-pressed', String(layout.galleryShown()));
      toolbar.button('panel').setAttribute('aria-pressed', String(layout.panelShown()));
    };
    layout.onChange(mark);
    mark();
  }

  // keepHash: a damaged link stays in the address bar (to be copied or fixed) while the
  // default example shows.
  async function openExample(id, { keepHash = false } = {}) {
    let entry = examples.find((e) => e.id === id);
    if (!entry) {
      notice = `unknown example "${id}"; opened "${examples[0].title}" instead`;
      entry = examples[0];
      keepHash = true; // the link's text stays to be fixed
    }
    const token = ++loadToken;
    linkPending = false;
    status.info(`loading ${entry.title}…`);
    let scene;
    try {
      scene = await loadExampleScene(entry);
    } catch (err) {
      if (token === loadToken) fail(err);
      return;
    }
    if (token !== loadToken) return;
    share.opening(); // an encode still in flight must not overwrite the example's hash
    if (!keepHash) writeExampleIdToHash(entry.id);
    // An example opens as its file says, on the default grid.
    Object.assign(state.grid, DEFAULT_GRID);
    panel.refreshGrid();
    const src = entry.source ? [entry.source.paper, entry.source.figure].filter(Boolean).join(', ') : '';
    showScene(scene, { exampleId: entry.id, title: src ? `${entry.title} (${src})` : entry.title });
  }

  // A link that cannot be read says why and opens the default example: never a blank page.
  async function openLink(text) {
    const token = ++loadToken;
    status.info('opening the shared link…');
    let linked;
    try {
      linked = await decodeFragment(text);
    } catch (err) {
      if (token !== loadToken) return;
      notice = `cannot open the link: ${err && err.message ? err.message : err}`;
      await openExample(examples[0].id, { keepHash: true });
      return;
    }
    if (token !== loadToken) return;
    Object.assign(state.grid, linked.grid || DEFAULT_GRID);
    panel.refreshGrid();
    linkPending = true;
    const title = typeof linked.scene.title === 'string' && linked.scene.title ? linked.scene.title : 'untitled scene';
    showScene(linked.scene, { title: `${title} (shared link)`, camera: linked.camera || null });
  }

  function openFromHash() {
    markHashShown();
    const h = readHash();
    if (h.kind === 'state') return openLink(h.text);
    return openExample(h.kind === 'example' ? h.id : examples[0].id);
  }

  // Sends the scene to the worker; the result comes back in applyResult (or applyFailure).
  function solveNow() {
    if (!state.scene) return;
    const edited = !opening && !quiet;
    opening = false;
    quiet = false;
    if (edited) undoRedo.touched();
    let text;
    try {
      text = state.text(); // a cyclic or too deep object throws here
    } catch (err) {
      applyFailure({ code: 'InvalidField', message: `the scene cannot be written as JSON: ${err.message}` }, { edited });
      return;
    }
    const grid = { nu: state.grid.nu, nv: state.grid.nv };
    solver.request({ scene: text, grid, options: { ...grid, ...analysis.solveOptions() }, edited, token: sceneToken, requestedAt: performance.now() });
  }

  applyFailure = (err, job) => {
    hooks.solveCount++;
    if (doc.solved(false, err)) return; // a checked edit (a picked blend) is undone and says why
    if (files.failed(err, job)) return; // an opened file's scene: the previous one comes back
    if (linkPending) {
      // The link decoded but its scene does not solve: nothing good to keep on screen.
      linkPending = false;
      notice = `cannot open the link: ${messageOf(err)}`;
      openExample(examples[0].id, { keepHash: true });
      return;
    }
    fail(err);
    panel.showSolveError(err && err.message ? err.message : String(err));
  };

  applyResult = (result, job, ms) => {
    hooks.solveCount++;
    // uvs and indices depend on the grid alone: built here once per grid, shared by the patches.
    const topology = gridTopology(job.grid.nu, job.grid.nv);
    for (const p of result.patches) {
      p.uvs = topology.uvs;
      p.indices = topology.indices;
    }
    linkPending = false;
    doc.solved(true);
    undoRedo.solved();
    bezier.solvedPatches(result.patches);
    viewer.setPatches(result.patches);
    building.drawn(result.patches, job.scene);
    analysis.solved(result, job.options);
    state.noteSolved(result.patches);
    if (cameraPending) viewer.setCamera(cameraPending);
    else if (fitPending) viewer.fit();
    cameraPending = null;
    fitPending = false;
    panel.showSolved(result.patches);
    hooks.lastError = null;
    if (!hooks.ready) hooks.readyAt = performance.now(); // first surface, from navigation start
    // The page path of this solve (request to drawn) against the worker's own time.
    hooks.lastSolve = { pageMs: performance.now() - job.requestedAt, workerMs: ms, ...job.grid };
    hooks.ready = true;
    const { nu, nv } = job.grid;
    const n = result.patches.length;
    const summary = `${n} ${n === 1 ? 'patch' : 'patches'}, grid ${nu}×${nv}, solved in ${ms.toFixed(1)} ms`;
    hooks.notice = notice;
    if (notice) status.error(notice);
    else status.info(summary);
    notice = null;
    share.solved(job.scene, job.grid, summary, job.edited || files.solved(job));
  };

  // A link pasted into the address bar or history navigation opens what it names;
  // the page's own writes (replaceState fires no hashchange anyway) never re-open.
  window.addEventListener('hashchange', () => {
    if (!hashIsShown()) openFromHash();
  });

  await openFromHash();
}

start().catch(fail);
