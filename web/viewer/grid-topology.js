// uvs and triangle indices of an (nu+1)×(nv+1) vertex grid: the same for every patch on the
// same grid, so the page builds them once per grid instead of receiving them with every solve.
// Must match the core's tessellation (cpp/surface/tessellate.cpp, buildGridData); a JS test
// compares the two.

let last = null;

/** { uvs: Float32Array(2·V), indices: Uint32Array(6·nu·nv) }, cached for the latest grid. */
export function gridTopology(nu, nv) {
  if (last && last.nu === nu && last.nv === nv) return last;
  const uvs = new Float32Array(2 * (nu + 1) * (nv + 1));
  for (let j = 0; j <= nv; j++)
    for (let i = 0; i <= nu; i++) {
      const k = j * (nu + 1) + i;
      uvs[2 * k] = Math.fround(i / nu);
      uvs[2 * k + 1] = Math.fround(j / nv);
    }
  const indices = new Uint32Array(6 * nu * nv);
  let t = 0;
  for (let j = 0; j < nv; j++)
    for (let i = 0; i < nu; i++) {
      const a = j * (nu + 1) + i, b = a + nu + 1, c = b + 1, d = a + 1;
      indices[t++] = a, indices[t++] = d, indices[t++] = b, indices[t++] = b, indices[t++] = d, indices[t++] = c;
    }
  last = { nu, nv, uvs, indices };
  return last;
}

/** Gives each solved patch of a grid { nu, nv } the grid's uvs and indices (shared). */
export function withGridTopology(patches, { nu, nv }) {
  const topology = gridTopology(nu, nv);
  for (const p of patches) {
    p.uvs = topology.uvs;
    p.indices = topology.indices;
  }
  return patches;
}
