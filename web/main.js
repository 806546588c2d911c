// The page, composed in two steps. First what a visitor sees: the status line, the solver
// worker's client (web/boot.js started the worker), the view and the surface the worker
// solved ahead (first-surface.js). Then the editor (editor.js, a chunk loaded after that
// frame): the document and its one door for edits, the scene session, the chrome and the
// features.
import { createViewer } from './viewer/viewer.js';
import { messageOf } from './state/document.js';
import { createSolverClient } from './solver/solver-client.js';
import { createStatus } from './ui/status.js';
import { loadExamplesAhead } from './state/examples.js';
import { readHash } from './state/hash.js';
import { installTestHooks } from './test-hooks.js';
import { createBezierFeature } from './features/bezier.js';
import { showSolvedAhead } from './first-surface.js';

// How long the page waits, once its view exists, for the first surface the worker solves
// ahead before it wires its features anyway (the worker may be slow to load).
const FIRST_SURFACE_WAIT_MS = 150;

const status = createStatus(document.getElementById('status'));
const titleEl = document.getElementById('scene-title');
let viewer = null;
let analysis = null;
const bezier = createBezierFeature();
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
  const relay = { result: () => {}, error: () => {}, report: () => {} };
  const solver = createSolverClient({
    onResult: (...args) => relay.result(...args),
    onError: (...args) => relay.error(...args),
    onReport: (...args) => relay.report(...args),
    onBusy: (ms) => status.busy(ms),
  });
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
  performance.mark('pdesurf:view-ready');
  // The example the worker solved ahead is drawn before the page is wired.
  await showSolvedAhead({ solver, viewer, waitMs: FIRST_SURFACE_WAIT_MS });
  // The catalogue and the scene (the worker fetched its own to solve ahead) are read after
  // that frame: before it, their requests would only hold connections the worker waits for.
  const loading = loadExamplesAhead(readHash());
  // The editor is a chunk of its own: its code is neither fetched nor parsed before that
  // frame; fetched beside the examples.
  const editorLoading = import('./editor.js');
  editorLoading.catch(() => {}); // reported below
  let examples;
  try {
    examples = await loading.index;
    await loading.scene;
  } catch (err) {
    fail(err);
    return;
  }
  let editor;
  try {
    editor = await editorLoading;
  } catch (err) {
    fail(new Error(`cannot load the editor: ${err.message}`));
    return;
  }
  await editor.startEditor({ examples, solver, relay, viewer, bezier, status, hooks, titleEl, fail,
    onAnalysis: (a) => { analysis = a; } });
}

start().catch(fail);
