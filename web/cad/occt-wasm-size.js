// The byte size of replicad-opencascadejs 1.1.0's replicad_single.wasm (package-lock.json):
// the total of its download when the server compresses it (web/cad/load-occt.js). A test
// checks it against the installed file (tests/js/read-step.test.mjs).
export const OCCT_WASM_BYTES = 22980267;
