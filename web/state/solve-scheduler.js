// Coalesce solve requests: any number of slider events within one frame cause one
// solve, run just before that frame is painted.

export function createSolveScheduler(solveNow) {
  let pending = false;
  return {
    request() {
      if (pending) return;
      pending = true;
      requestAnimationFrame(() => {
        pending = false;
        solveNow();
      });
    },
  };
}
