// Coalesce solve requests: any number of slider events within one frame cause one
// solve, run just before that frame is painted.

export function createSolveScheduler(solveNow) {
  let pending = 0; // the animation frame a request waits for
  return {
    request() {
      if (pending) return;
      pending = requestAnimationFrame(() => {
        pending = 0;
        solveNow();
      });
    },
    /** At once: a scene just opened has nothing to coalesce with (a waiting request is moot). */
    now() {
      cancelAnimationFrame(pending);
      pending = 0;
      solveNow();
    },
  };
}
