// window.__pdesurf: read-only view of the page for the browser tests (and for
// debugging from the console). The page updates the plain fields as it goes.

/** Order-sensitive summary of the drawn positions: Σ (k+1)·(|x|+|y|+|z|) / V per array. */
export function checksumOf(arrays) {
  let total = 0;
  for (const a of arrays) {
    const V = a.length / 3;
    let s = 0;
    for (let k = 0; k < V; k++) {
      s += (k + 1) * (Math.abs(a[3 * k]) + Math.abs(a[3 * k + 1]) + Math.abs(a[3 * k + 2]));
    }
    total += V > 0 ? s / V : 0;
  }
  return total;
}

/** extras: further read-only functions (the bezier overlays and editor, given by main.js). */
export function installTestHooks(getPositionArrays, getCamera = () => null, extras = {}) {
  const hooks = {
    ready: false, // true once the first result is handled (after its frame: the panel built)
    readyAt: null, // performance.now() then, from navigation start
    firstFrameAt: null, // performance.now() once the first frame showing a surface is presented
    firstFrameInfo: null, // { calls, programs } of that frame
    surfaceBeforePanel: false, // the first result came within FIRST_PANEL_WAIT_MS: drawn before the panel was built
    lastSolve: null, // { pageMs, workerMs, nu, nv, solvedAhead, resolved } of the latest drawn solve
    solveCount: 0, // solve attempts, failed ones included
    lastError: null, // message of the latest failure; null after a good solve
    exampleId: null, // null while a scene from a shared link is open
    notice: null, // the last notice shown instead of a solve summary (bad link, unknown example)
    lastLink: null, // the URL the last "copy link" produced
    // the last export or opened file: { action, name, bytes?, ms?, error? } (web/features/files.js);
    // a CAD export (step, iges, 3dm) adds { tolerance, fitMs, faces: [{ name, deviation, ... }] }
    lastFile: null,
    history: () => null, // { canUndo, canRedo, depth, redoDepth }, set by web/features/history.js
    checksum: () => checksumOf(getPositionArrays()),
    vertexCount: () => getPositionArrays().reduce((n, a) => n + a.length / 3, 0),
    camera: () => getCamera(), // { position, target } as a link stores it
    ...extras,
  };
  window.__pdesurf = hooks;
  return hooks;
}
