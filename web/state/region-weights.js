// Per-region weights of a discrete normal field (docs/bezier.md): the (np+1)×(mp+1)
// sample grid is split into 3×3 regions, and a sample's λ weight is its region's value.
// The page edits nine numbers; the scene stores the full per-sample list the solver
// reads (`normals.lambda_weights`, row i major: sample (i, j) at i*(mp+1) + j, u = i/np).

export const SPLIT = 3; // regions per direction
export const WEIGHT_MIN = 0;
export const WEIGHT_MAX = 10;
export const DEFAULT_WEIGHT = 1; // the solver's weight when the scene gives none

const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
const isCount = (n) => Number.isInteger(n) && n >= 1;

/** [np, mp] of a discrete normal field, or null (continuous field, or not a grid). */
export function discreteGrid(patch) {
  const g = isObject(patch) && isObject(patch.normals) ? patch.normals.grid : null;
  return Array.isArray(g) && g.length === 2 && isCount(g[0]) && isCount(g[1]) ? [g[0], g[1]] : null;
}

/** The region (0..SPLIT-1) of sample k of `count`: even runs, the earlier ones take the remainder. */
export function regionOf(k, count) {
  return Math.min(SPLIT - 1, Math.floor((SPLIT * k) / count));
}

/** First and last sample index of region r among `count` samples. */
export function regionSamples(r, count) {
  let first = -1;
  let last = -1;
  for (let k = 0; k < count; k++) {
    if (regionOf(k, count) !== r) continue;
    if (first < 0) first = k;
    last = k;
  }
  return [first, last];
}

/** The parameter span [first/n, last/n] of region r on a direction with n intervals. */
export function regionSpan(r, n) {
  const [first, last] = regionSamples(r, n + 1);
  return [first / n, last / n];
}

/** The per-sample list for nine region values (row-major: regions[ru*SPLIT + rv]). */
export function regionWeightsArray(np, mp, regions) {
  if (!isCount(np) || !isCount(mp)) throw new Error(`sample grid must be positive integers, not ${np}×${mp}`);
  if (!Array.isArray(regions) || regions.length !== SPLIT * SPLIT || !regions.every(Number.isFinite)) {
    throw new Error(`expected ${SPLIT * SPLIT} finite region weights`);
  }
  const out = new Array((np + 1) * (mp + 1));
  for (let i = 0; i <= np; i++) {
    const ru = regionOf(i, np + 1);
    for (let j = 0; j <= mp; j++) out[i * (mp + 1) + j] = regions[ru * SPLIT + regionOf(j, mp + 1)];
  }
  return out;
}

/**
 * Nine slider values from a scene's lambda_weights: each region's mean (clamped to the
 * slider range). Anything but a numeric list of the right length (absent, an
 * expression) reads as the default weight everywhere.
 */
export function regionValuesFrom(weights, np, mp) {
  const values = new Array(SPLIT * SPLIT).fill(DEFAULT_WEIGHT);
  if (!Array.isArray(weights) || weights.length !== (np + 1) * (mp + 1) || !weights.every(Number.isFinite)) return values;
  const sums = new Array(SPLIT * SPLIT).fill(0);
  const counts = new Array(SPLIT * SPLIT).fill(0);
  for (let i = 0; i <= np; i++) {
    for (let j = 0; j <= mp; j++) {
      const r = regionOf(i, np + 1) * SPLIT + regionOf(j, mp + 1);
      sums[r] += weights[i * (mp + 1) + j];
      counts[r]++;
    }
  }
  // A sum of equal weights over their count is not always that weight (9.8 comes back as
  // 9.800000000000006): 12 digits give a region's own value back, as its slider showed it.
  const mean = (r) => Number((sums[r] / counts[r]).toPrecision(12));
  return values.map((v, r) => (counts[r] ? Math.min(WEIGHT_MAX, Math.max(WEIGHT_MIN, mean(r))) : v));
}

/**
 * Write the regions into the patch's normals.lambda_weights; all at the default weight
 * removes the field instead, which the solver reads the same and keeps links short.
 */
export function setRegionWeights(patch, regions) {
  const grid = discreteGrid(patch);
  if (!grid) throw new Error(`patch ${JSON.stringify(patch?.name)} has no discrete normal field`);
  if (regions.every((w) => w === DEFAULT_WEIGHT)) {
    delete patch.normals.lambda_weights;
    return null;
  }
  patch.normals.lambda_weights = regionWeightsArray(grid[0], grid[1], regions);
  return patch.normals.lambda_weights;
}
