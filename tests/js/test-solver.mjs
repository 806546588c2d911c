// The page's solver wrapper (web/solver/pdesurf-solver.js) over the built wasm module, for the
// JS tests: PDESURF_BUILD_DIR (default build/) says where, as in scripts/test.
import { readFileSync } from 'node:fs';
import { loadSolver } from '../../web/solver/pdesurf-solver.js';

export const wasmDir = new URL(`${process.env.PDESURF_BUILD_DIR ?? 'build'}/wasm/`, new URL('../../', import.meta.url));

export function loadTestSolver() {
  return loadSolver({
    moduleUrl: new URL('pdesurf.js', wasmDir).href,
    wasmBinary: readFileSync(new URL('pdesurf.wasm', wasmDir)),
  });
}
