// A cold start's first solve, done ahead in the solver worker: web/boot.js starts the worker
// with the page's hash in its URL; the worker fetches the example it names (the first of the
// catalogue without one) and solves it with the options a page opens an example with, while
// the page's own modules still load. The result goes to the page unasked (solver-client.js
// keeps it for a first request of exactly that scene text and those options), or to a
// request that arrives while it is still being solved. State links (#s=…) are not solved
// ahead: the page decodes them.
import { loadExampleIndex, loadExampleScene } from '../state/examples.js';
import { readHash } from '../state/hash.js';
import { DEFAULT_GRID } from '../state/scene-state.js';
import { sameSolve } from './same-solve.js';

// What scene-session.js sends when an example opens: the default grid, flat shading (no
// curvature), the join report, no crossing test (features/analysis.js solveOptions).
export const OPENING_OPTIONS = Object.freeze({ ...DEFAULT_GRID, curvature: false, joins: true, crossings: false });

/**
 * ready: promise of the solver; solve(solver, sceneText, options) -> [result, transfer];
 * post({ scene, options, result, ms }, transfer): sends the result to the page unasked, or
 * { result: null } when none will come (a state link, a failure: the page then stops waiting).
 * start(pageHash) begins once; take(sceneText, options) -> promise of { result, transfer, ms }
 * for a request that arrives before the result was posted and asks for that scene, else null.
 */
export function createAheadSolve(ready, solve, post) {
  let pending = null; // promise of { scene, options, result, transfer, ms } or null
  let claimed = false; // posted, or taken by a request: one use (its buffers move)
  return {
    start(pageHash) {
      if (pending) return;
      const h = readHash(pageHash);
      if (h.kind === 'state') {
        post({ result: null }, []); // nothing ahead: the page decodes its link
        return;
      }
      pending = (async () => {
        const list = await loadExampleIndex();
        const entry = list.find((e) => e.id === h.id) || list[0];
        const scene = JSON.stringify(await loadExampleScene(entry));
        const solver = await ready;
        const t0 = performance.now();
        const [result, transfer] = solve(solver, scene, OPENING_OPTIONS);
        result.solvedAhead = true; // for the page's tests (hooks.lastSolve)
        return { scene, options: OPENING_OPTIONS, result, transfer, ms: performance.now() - t0 };
      })().catch(() => null); // the page's own request reports any failure
      pending.then((done) => {
        if (claimed) return;
        claimed = true;
        if (!done) post({ result: null }, []); // the page need not wait for it
        else post({ scene: done.scene, options: done.options, result: done.result, ms: done.ms }, done.transfer);
      });
    },
    async take(scene, options) {
      if (!pending || claimed) return null;
      claimed = true;
      const done = await pending;
      return done && sameSolve(done, { scene, options }) ? done : null;
    },
  };
}
