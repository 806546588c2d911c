// Open CASCADE in wasm (replicad's build of opencascade.js) loaded on first use, once: imported
// and started when the first STEP file is opened, never at page load.
import { OCCT_URL } from './occt-url.js';

let started = null;

/** The started module (a promise shared by every caller; a failure may be retried). */
export function loadOcct() {
  started ??= import(OCCT_URL)
    .then((mod) => mod.default()) // the glue fetches its wasm beside itself (node: tests/js/read-step.test.mjs gives it)
    .catch((err) => {
      started = null;
      throw new Error(`cannot load Open CASCADE from ${OCCT_URL}: ${err?.message ?? err}`);
    });
  return started;
}
