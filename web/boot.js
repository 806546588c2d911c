// Starts the solver worker as soon as the page is parsed, before the page's modules have
// loaded and run (the worker then loads the wasm module in parallel with them);
// solver/solver-client.js adopts it. data-worker: the worker's URL, relative to the page
// (the production build points it at its bundle). The production build inlines this file
// into its page (scripts/build-web.mjs; the static server allows it by its hash), so the
// worker starts as the page is parsed, not a round trip later.
(() => {
  const script = document.currentScript;
  try {
    // The page's hash goes along: the worker solves the example it names ahead
    // (solver/ahead-solve.js).
    const url = new URL(script.dataset.worker, location.href);
    url.hash = new URLSearchParams({ first: location.hash }).toString();
    const worker = new Worker(url, { type: 'module' });
    worker.onerror = (e) => {
      e.preventDefault();
      worker.failed = true; // the client starts a fresh one
    };
    window.__pdesurfEarlyWorker = worker;
  } catch {
    // The client starts its own.
  }
})();
