// Where rhino3dm's ES module is, for the sources (node, and the page's /node_modules/, which
// the static server serves). scripts/build-web.mjs swaps this file for one naming the copy
// beside the bundle. A URL, not the bare 'rhino3dm': workers have no importmap, and the
// bundler must not pull 2.7 MB of wasm glue into a chunk.
export const RHINO3DM_URL = new URL('../../node_modules/rhino3dm/rhino3dm.module.min.js', import.meta.url).href;
