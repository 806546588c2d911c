// rhino3dm (openNURBS in wasm, ~2.7 MB) loaded on first use, once: the module is imported and
// started when the first .3dm file is written, never at page load.
import { RHINO3DM_URL } from './rhino3dm-url.js';

let started = null;

/** rhino3dm's started module (a promise shared by every caller; a failure may be retried). */
export function loadRhino3dm() {
  started ??= import(RHINO3DM_URL)
    .then((mod) => mod.default())
    .catch((err) => {
      started = null;
      throw new Error(`cannot load rhino3dm from ${RHINO3DM_URL}: ${err?.message ?? err}`);
    });
  return started;
}
