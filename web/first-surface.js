// A cold start's first frame: the example the solver worker solved ahead
// (solver/ahead-solve.js) is drawn as soon as the view exists, before the page's panel,
// gallery and editing features are built and wired; scene-session.js adopts it when the
// example opens (it is not drawn again). On two cores the page's wiring and the worker's
// first solve otherwise run in turn before anything is drawn.
import { withGridTopology } from './viewer/grid-topology.js';

/**
 * solver: solver/solver-client.js; viewer: viewer/viewer.js. Resolves true once the surface
 * solved ahead is on screen, false at once if none will come, or after waitMs if it has not
 * come by then (the page goes on; its first request will take it when it comes).
 */
export function showSolvedAhead({ solver, viewer, waitMs }) {
  return new Promise((resolve) => {
    let timer = 0;
    let heard = false; // the worker's answer came (maybe at once): no more waiting
    const stop = solver.onAhead((msg) => {
      heard = true;
      clearTimeout(timer);
      if (!msg) {
        resolve(false);
        return;
      }
      viewer.setPatches(withGridTopology(msg.result.patches, msg.options));
      viewer.fit();
      viewer.afterNextFrame(() => {
        solver.certifyAhead();
        resolve(true);
      });
    });
    if (!heard) {
      timer = setTimeout(() => {
        stop();
        resolve(false);
      }, waitMs);
    }
  });
}
