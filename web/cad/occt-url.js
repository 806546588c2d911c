// Where Open CASCADE's wasm build (replicad-opencascadejs: STEP reading, 23 MB of wasm) is, for
// the sources (node, and the page's /node_modules/, which the static server serves).
// scripts/build-web.mjs swaps this file for one naming the copy beside the bundle. A URL, not a
// bare name: workers have no importmap, and the bundler must not pull the glue into a chunk.
export const OCCT_URL = new URL('../../node_modules/replicad-opencascadejs/dist/replicad_single.js', import.meta.url).href;
