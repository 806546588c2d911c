// Benchmark (scripts/bench-page.mjs): the page's solver wrapper in a Chromium worker of its
// own, no page around it — the solver-only time of a slider step, to set beside the page's.
// In: { scene (text), params: [names], runs }; out: { [name]: median ms } or { error }.
import { loadSolver } from '/web/solver/pdesurf-solver.js';

self.onmessage = async ({ data: { scene, params, runs = 21 } }) => {
  try {
    const solver = await loadSolver({ moduleUrl: '/wasm/pdesurf.js' });
    const j = JSON.parse(scene);
    // The options the page's worker solves with (solver-worker.js: the report comes after).
    const options = { nu: 64, nv: 64, curvature: false, joins: false, topology: false };
    for (let k = 0; k < 20; k++) solver.solve(JSON.stringify(j), options); // past the engine's tier-up
    const out = {};
    for (const name of params) {
      const base = j.parameters[name].value, times = [];
      for (let k = 0; k < runs; k++) {
        j.parameters[name].value = base + 0.001 * ((k % 3) + 1);
        const text = JSON.stringify(j);
        const t = performance.now();
        solver.solve(text, options);
        times.push(performance.now() - t);
      }
      j.parameters[name].value = base;
      times.sort((a, b) => a - b);
      out[name] = times[Math.floor(runs / 2)];
    }
    self.postMessage(out);
  } catch (e) {
    self.postMessage({ error: String(e?.stack || e) });
  }
};
