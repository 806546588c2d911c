// The page's .3dm writer runs here, not on the page: rhino3dm's embind glue builds its
// functions with new Function, which the page's CSP refuses. The static server sends this
// script a policy of its own that allows eval (scripts/static-server.mjs); a worker has no
// DOM and sees only the surfaces it is sent. Messages: { id, surfaces, tolerance, title, breps, archive } in,
// { id, bytes } or { id, error } out.
import { write3dm } from './write-3dm.js';

self.onmessage = async ({ data: { id, surfaces, tolerance, title, breps, archive } }) => {
  try {
    const bytes = await write3dm(surfaces, { tolerance, title, breps, archive });
    self.postMessage({ id, bytes }, [bytes.buffer]);
  } catch (err) {
    self.postMessage({ id, error: String(err?.message ?? err) });
  }
};
