// The scene on screen and its solves: opening an example, a link, a file or a built scene;
// putting back an undo step; sending the scene to the worker and drawing what comes back.
// Features hear about it through the document's signals (web/state/document.js):
//   'opened'  (scene, { exampleId, title })  another scene is on screen (fresh overlays)
//   'restored' (scene)                       an undo or redo within the same scene
//   'solved'  (result, job)                  a good solve, before it is drawn
//   'drawn'   (result, job)                  after it is drawn (result.reportPending: its join
//                                            report, asked for, comes after)
//   'certified' (report, job)                the join report of the solve last drawn
// Opening and links stay explicit (share, files, history): they decide what a solve means.
import { withGridTopology } from './viewer/grid-topology.js';
import { DEFAULT_GRID } from './state/scene-state.js';
import { kindInfo } from './state/patch-kinds.js';
import { loadExampleScene } from './state/examples.js';
import { readHash, writeExampleIdToHash, markHashShown, hashIsShown } from './state/hash.js';
import { decodeFragment } from './link/link-codec.js';
import { createSolveScheduler } from './state/solve-scheduler.js';
import { messageOf } from './state/document.js';

// How long a cold start's first solve may keep the panel unbuilt (a solve ahead is drawn
// well within it; a slow one shows the panel meanwhile).
const FIRST_PANEL_WAIT_MS = 150;

/**
 * doc, solver (solver/solver-client.js) and relay ({ result, error }: where its answers go),
 * viewer, panel, gallery, status, hooks, titleEl, examples (the index), fail(err);
 * later attach({ share, files, history, solveOptions }).
 */
export function createSceneSession({ doc, solver, relay, viewer, panel, gallery, status, hooks, titleEl, examples, fail }) {
  const { state } = doc;
  let parts = null; // { share, files, history, solveOptions } once attached
  let sceneToken = 0; // a new scene (example or link): results for an older one are dropped
  let loadToken = 0; // a slower fetch or decode of an earlier pick must not win
  let fitPending = false; // frame the camera on the first good solve of an example
  let cameraPending = null; // or restore a shared link's camera instead
  let linkPending = false; // a link's scene that has not solved yet
  let opening = false; // the next solve opens a scene (not a user's change)
  let quiet = false; // the next solve only adds analysis data: not a user's edit
  let notice = null; // shown instead of the solve summary once (e.g. a bad link)
  // The page's first scene: its surface is drawn before its panel and gallery entry are built
  // and the page's chrome is laid out (about 80 ms of DOM work and text layout, which would
  // hold the first frame back), then they follow.
  let presentLater = null;
  let presentTimer = 0;
  let presentedOnce = false;

  // The wasm module lives in a worker (solver/solver-worker.js): no solve on this thread.
  relay.result = applyResult;
  relay.error = applyFailure;
  relay.report = applyReport;
  let drawnJob = null; // the job of the solve last drawn
  let earlyReport = null; // { report, job }: a report that came before its solve was drawn (the first scene's)
  hooks.solverRestarts = () => solver.restarts;
  const scheduler = createSolveScheduler(solveNow);

  // Another scene on screen: its title, panel and gallery entry, and the camera it comes
  // with (else framed on its first solve); features reset on 'opened'.
  function present(scene, exampleId, title, camera) {
    titleEl.textContent = title;
    cameraPending = camera;
    fitPending = !camera;
    const show = () => {
      document.body.classList.remove('starting');
      panel.showScene(scene);
      gallery.setActive(exampleId, typeof scene.description === 'string' ? scene.description : '');
      doc.emit('opened', scene, { exampleId, title });
    };
    if (presentedOnce) show();
    else {
      // The page's first scene: shown by applyResult after its first frame, by any other
      // change, or after FIRST_PANEL_WAIT_MS if its solve takes longer (the panel is then
      // there to edit while it runs).
      presentLater = show;
      presentTimer = setTimeout(flushPresent, FIRST_PANEL_WAIT_MS);
    }
    presentedOnce = true;
  }

  // Anything but the first result's drawing needs the scene presented first.
  function flushPresent() {
    clearTimeout(presentTimer);
    const show = presentLater;
    presentLater = null;
    show?.();
  }

  // Shared by examples, links, files and built scenes: the scene becomes the page state.
  // solveAtOnce: the request leaves before the panel and the gallery are built, not at the
  // next frame (an example or a link: nothing follows that could change it; on a cold
  // start the worker waits idle and that frame is the page's first layout).
  function showScene(scene, { exampleId = null, title, camera = null, solveAtOnce = false }) {
    flushPresent();
    sceneToken++;
    parts.share.opening();
    opening = true;
    state.setScene(scene, exampleId);
    doc.reset();
    hooks.exampleId = exampleId;
    if (solveAtOnce) scheduler.now();
    present(scene, exampleId, title, camera);
    if (!solveAtOnce) scheduler.request();
    parts.history.opened();
    return sceneToken;
  }

  // An undo or redo: the snapshot's scene, grid and title come back and re-solve as an edit
  // (the hash follows). The camera stays within a scene; another scene comes back with the
  // view it was left with (`camera`), or framed.
  function restoreScene({ sceneText, grid, exampleId, title }, camera) {
    flushPresent();
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
      doc.emit('restored', scene);
    } else present(scene, exampleId, title, camera);
    scheduler.request();
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
    parts.share.opening(); // an encode still in flight must not overwrite the example's hash
    if (!keepHash) writeExampleIdToHash(entry.id);
    // An example opens as its file says, on the default grid.
    Object.assign(state.grid, DEFAULT_GRID);
    panel.refreshGrid();
    const src = entry.source ? [entry.source.paper, entry.source.figure].filter(Boolean).join(', ') : '';
    showScene(scene, { exampleId: entry.id, title: src ? `${entry.title} (${src})` : entry.title, solveAtOnce: true });
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
    showScene(linked.scene, { title: `${title} (shared link)`, camera: linked.camera || null, solveAtOnce: true });
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
    if (edited) parts.history.touched();
    let text;
    try {
      text = state.text(); // a cyclic or too deep object throws here
    } catch (err) {
      applyFailure({ code: 'InvalidField', message: `the scene cannot be written as JSON: ${err.message}` }, { edited });
      return;
    }
    const grid = { nu: state.grid.nu, nv: state.grid.nv };
    solver.request({ scene: text, grid, options: { ...grid, ...parts.solveOptions() }, edited, token: sceneToken, requestedAt: performance.now() });
  }

  // The join report of a drawn solve (the worker certifies after drawing).
  function applyReport(report, job, ms, timing = {}) {
    if (job !== drawnJob) {
      earlyReport = { report, job, ms, timing };
      return;
    }
    hooks.reportPending = false;
    hooks.reportCount = (hooks.reportCount ?? 0) + 1;
    // For the tests: when it came (after its solve was drawn), the worker's time for it and the
    // longest it held the worker at once (what an edit may wait behind it).
    hooks.lastReport = { ms, longestSliceMs: timing.longestSliceMs, solveCount: hooks.solveCount, at: performance.now(), requestedAt: job.requestedAt };
    doc.emit('certified', report, job);
  }

  function applyFailure(err, job) {
    flushPresent();
    hooks.solveCount++;
    if (doc.solved(false, err)) return; // a checked edit (a picked blend) is undone and says why
    if (parts.files.failed(err, job)) return; // an opened file's scene: the previous one comes back
    if (linkPending) {
      // The link decoded but its scene does not solve: nothing good to keep on screen.
      linkPending = false;
      notice = `cannot open the link: ${messageOf(err)}`;
      openExample(examples[0].id, { keepHash: true });
      return;
    }
    fail(err);
    panel.showSolveError(err && err.message ? err.message : String(err));
  }

  // The patches on screen, and the camera a new scene comes with (or framed on them).
  function draw(result, job) {
    // uvs and indices depend on the grid alone: built once per grid, shared by the patches.
    viewer.setPatches(withGridTopology(result.patches, job.grid));
    if (cameraPending) viewer.setCamera(cameraPending);
    else if (fitPending) viewer.fit();
    cameraPending = null;
    fitPending = false;
  }

  // drawn: the first scene's surface, already drawn before its panel was built.
  function applyResult(result, job, ms, drawn = false) {
    if (presentLater) {
      // The first scene: its surface on screen first, then its panel (present).
      hooks.surfaceBeforePanel = true;
      const token = sceneToken;
      const thenPresent = () => {
        if (token !== sceneToken) return; // another scene was opened meanwhile
        flushPresent();
        applyResult(result, job, ms, true);
      };
      if (viewer.shows(result.patches)) {
        // Drawn, and its frame shown, before the page was wired (first-surface.js), framed.
        cameraPending = null;
        fitPending = false;
        thenPresent();
      } else {
        draw(result, job);
        viewer.afterNextFrame(thenPresent);
      }
      return;
    }
    hooks.solveCount++;
    linkPending = false;
    doc.solved(true);
    parts.history.solved();
    state.noteSolved(result.patches);
    doc.emit('solved', result, job);
    if (!drawn) draw(result, job);
    drawnJob = job;
    hooks.reportPending = Boolean(result.reportPending);
    hooks.lastDrawnAt = performance.now();
    doc.emit('drawn', result, job);
    if (earlyReport?.job === job) applyReport(earlyReport.report, job, earlyReport.ms, earlyReport.timing);
    earlyReport = null;
    panel.showSolved(result.patches);
    hooks.lastError = null;
    if (!hooks.ready) hooks.readyAt = performance.now(); // first result handled (its frame already shown)
    // The page path of this solve (request to drawn) against the worker's own time.
    hooks.lastSolve = { pageMs: performance.now() - job.requestedAt, workerMs: ms, ...job.grid, solvedAhead: Boolean(result.solvedAhead),
      // Which pde patches the module solved again (the others' problems did not change).
      resolved: result.patches.filter((p) => p.reused === false && kindInfo(p.kind).pde).map((p) => p.name) };
    hooks.ready = true;
    const { nu, nv } = job.grid;
    const n = result.patches.length;
    const summary = `${n} ${n === 1 ? 'patch' : 'patches'}, grid ${nu}×${nv}, solved in ${ms.toFixed(1)} ms`;
    hooks.notice = notice;
    if (notice) status.error(notice);
    else status.info(summary);
    notice = null;
    parts.share.solved(job.scene, job.grid, summary, job.edited || parts.files.solved(job));
  }

  // A link pasted into the address bar or history navigation opens what it names;
  // the page's own writes (replaceState fires no hashchange anyway) never re-open.
  window.addEventListener('hashchange', () => {
    if (!hashIsShown()) openFromHash();
  });

  return {
    scheduler,
    attach(p) {
      parts = p;
    },
    showScene,
    restoreScene,
    openExample,
    openFromHash,
    /** A scene built in the page (new scene): the user's, so its link is written at its first solve. */
    openBuilt(scene, title) {
      showScene(scene, { title });
      opening = false;
    },
    /** A solve that only adds analysis data: not a user's edit. */
    requestQuiet() {
      quiet = true;
      scheduler.request();
    },
    setNotice(text) {
      notice = text;
    },
  };
}
