// Open CASCADE's wasm build runs here, not on the page: its embind glue builds functions with
// new Function, which the page's CSP refuses. The static server sends this script a policy of
// its own that allows eval (scripts/static-server.mjs), as for rhino3dm's worker. Started on
// the first STEP file opened. Messages: { id, read: bytes, fileName } in; { id, scene } or
// { id, error, code } out, and before them, while Open CASCADE's wasm is fetched the first
// time, { id, progress: { loaded, total } } (bytes; at most one a percent).
import { readStep } from './read-step.js';

self.onmessage = async ({ data: { id, read, fileName } }) => {
  let told = -1;
  const onLoadProgress = (loaded, total) => {
    const percent = Math.floor((100 * loaded) / total);
    if (percent === told) return;
    told = percent;
    self.postMessage({ id, progress: { loaded, total } });
  };
  try {
    self.postMessage({ id, scene: await readStep(read, { fileName, onLoadProgress }) });
  } catch (err) {
    self.postMessage({ id, error: String(err?.message ?? err), code: err?.code ?? null });
  }
};
