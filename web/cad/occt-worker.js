// Open CASCADE's wasm build runs here, not on the page: its embind glue builds functions with
// new Function, which the page's CSP refuses. The static server sends this script a policy of
// its own that allows eval (scripts/static-server.mjs), as for rhino3dm's worker. Started on
// the first STEP file opened. Messages: { id, read: bytes, fileName } in; { id, scene } or
// { id, error, code } out.
import { readStep } from './read-step.js';

self.onmessage = async ({ data: { id, read, fileName } }) => {
  try {
    self.postMessage({ id, scene: await readStep(read, { fileName }) });
  } catch (err) {
    self.postMessage({ id, error: String(err?.message ?? err), code: err?.code ?? null });
  }
};
