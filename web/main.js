// The page, composed: the solver worker (started first, so the module loads while the view
// and the examples do), the view, the document and its one door for edits
// (state/document.js), the scene session (scene-session.js: openings, solves, drawing) and
// the features, each subscribing to the document's signals: panel, edits, history,
// Bézier editing, share, files, building, analysis.
import { createViewer } from './viewer/viewer.js';
import { createPanelWiring } from './panel-wiring.js';
import { createDocument, messageOf } from './state/document.js';
import { createSolverClient } from './solver/solver-client.js';
import { subscribeToEdits } from './edit-subscribers.js';
import { createGallery } from './ui/gallery.js';
import { createStatus } from './ui/status.js';
import { createToolbar } from './ui/toolbar.js';
import { createLayout } from './ui/layout.js';
import { createHelpOverlay } from './ui/help-overlay.js';
import { watchNumberControls } from './ui/number-access.js';
import { installShortcuts } from './keyboard-shortcuts.js';
import { createSceneState } from './state/scene-state.js';
import { loadExamplesAhead } from './state/examples.js';
import { readHash } from './state/hash.js';
import { installTestHooks } from './test-hooks.js';
import { createBezierWiring } from './bezier-wiring.js';
import { createShareWiring } from './share-wiring.js';
import { createAnalysisWiring } from './analysis-wiring.js';
import { createFileWiring } from './file-wiring.js';
import { createHistoryWiring } from './history-wiring.js';
import { createBuildWiring } from './build-wiring.js';
import { createSceneSession } from './scene-session.js';
import { showSolvedAhead } from './first-surface.js';

// How long the page waits, once its view exists, for the first surface the worker solves
// ahead before it wires its features anyway (the worker may be slow to load).
const FIRST_SURFACE_WAIT_MS = 150;

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

// Shown in the status line; the surfaces already drawn stay as they are. The page's chrome,
// hidden until the first scene is presented (scene-session.js), shows what there is of it.
function fail(err) {
  document.body.classList.remove('starting');
  const msg = messageOf(err);
  hooks.lastError = msg;
  status.error(msg);
}

async function start() {
  // Results reach the session once it exists (it needs the examples and the view).
  const relay = { result: () => {}, error: () => {} };
  const solver = createSolverClient({
    onResult: (...args) => relay.result(...args),
    onError: (...args) => relay.error(...args),
    onBusy: (ms) => status.busy(ms),
  });
  // The catalogue and the scene are preloaded by the page (and solved ahead by the worker);
  // they are read once the first surface is drawn.
  const loading = loadExamplesAhead(readHash());
  loading.index.catch(() => {}); // reported below
  try {
    viewer = createViewer(document.getElementById('viewport'), bezier.viewerHandlers, {
      onFirstSurfaceFrame: (at) => {
        hooks.firstFrameAt = at;
        // That frame's draw calls and the shader programs built for it (a cold start's cost).
        hooks.firstFrameInfo = { calls: viewer.renderer.info.render.calls, programs: viewer.renderer.info.programs.length };
      },
    });
  } catch (err) {
    fail(new Error(`cannot start WebGL: ${err.message}`));
    return;
  }
  // The example the worker solved ahead is drawn before the page is wired.
  await showSolvedAhead({ solver, viewer, waitMs: FIRST_SURFACE_WAIT_MS });
  let examples;
  try {
    examples = await loading.index;
    await loading.scene;
  } catch (err) {
    fail(err);
    return;
  }
  const state = createSceneState();
  hooks.sceneText = () => state.text();
  const doc = createDocument(state);
  let share = null;
  const panel = createPanelWiring({ doc, share: () => share, bezier });
  let session = null;
  const gallery = createGallery(document.getElementById('gallery'), examples, (id) => session.openExample(id), layout);
  session = createSceneSession({ doc, solver, relay, viewer, panel, gallery, status, hooks, titleEl, examples, fail });
  // For scripts/bench-page.mjs: a grid past the panel's 256 (the page path at 1024²).
  hooks.requestGrid = (nu, nv) => {
    Object.assign(state.grid, { nu, nv });
    session.scheduler.request();
  };
  subscribeToEdits(doc, { panel, status, scheduler: session.scheduler });
  doc.on('opened', () => viewer.resetOverlays());

  watchNumberControls(panel.gui);
  // At small sizes the panel is a sheet: its title bar closes it rather than folding it.
  panel.gui.$title.addEventListener('click', () => {
    if (panel.gui._closed && layout.isCompact()) {
      panel.gui.open();
      layout.showPanel(false);
    }
  });
  const undoRedo = createHistoryWiring({
    hooks, restore: session.restoreScene, camera: () => viewer.getCamera(),
    read: () => ({ sceneText: state.text(), grid: { ...state.grid }, exampleId: state.exampleId, title: titleEl.textContent }),
  });
  addToolbarButtons(undoRedo);
  // An edit the solver judges is a step only once it is kept.
  doc.on('judging', () => undoRedo.hold());
  doc.on('judged', (kept) => undoRedo.release(kept));
  installShortcuts({ fit: () => viewer.fit(true), help, layout });

  bezier.connect({ state, viewer, panel, doc, status });
  share = createShareWiring({ viewer, panel, status, hooks });
  const files = createFileWiring({ panel, viewer, state, status, hooks, solver, showScene: session.showScene,
    currentTitle: () => titleEl.textContent, setNotice: session.setNotice });
  createBuildWiring({ doc, panel, viewer, hooks, openBuilt: session.openBuilt });
  analysis = createAnalysisWiring({ doc, panel, viewer, hasAnalysis: true, requestSolve: session.requestQuiet });
  session.attach({ share, files, history: undoRedo, solveOptions: () => analysis.solveOptions() });
  await session.openFromHash();
}

function addToolbarButtons(undoRedo) {
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

start().catch(fail);
