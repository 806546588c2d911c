// The colour scale of a curvature map: which value range the colour ramp spans.
// Pure (no DOM, no three.js) so the rules can be unit-tested.
//   symmetric:  [-L, L] with L the p-th percentile of |k| (p = 100: the largest |k|)
//   percentile: [P(100 - p), P(p)] of k
//   fixed:      [min, max] as typed
// Values outside the range take the end colours ("clamped"). Degenerate vertices
// (poles, zero speed) carry 0 in the module's arrays; they are counted, not excluded.

export const SCALES = ['symmetric', 'percentile', 'fixed'];

/** The q-quantile (0..1) of a sorted Float64Array, linearly interpolated. */
export function quantile(sorted, q) {
  const n = sorted.length;
  if (n === 0) return 0;
  const x = Math.min(Math.max(q, 0), 1) * (n - 1);
  const i = Math.floor(x);
  const f = x - i;
  return i + 1 < n ? sorted[i] * (1 - f) + sorted[i + 1] * f : sorted[i];
}

/** Every finite value of the arrays, sorted, and how many were not finite. */
export function sortedValues(arrays) {
  let n = 0;
  for (const a of arrays) n += a.length;
  const out = new Float64Array(n);
  let k = 0;
  let nonFinite = 0;
  for (const a of arrays) {
    for (let i = 0; i < a.length; i++) {
      if (Number.isFinite(a[i])) out[k++] = a[i];
      else nonFinite++;
    }
  }
  const values = out.subarray(0, k).sort();
  return { values, nonFinite };
}

/**
 * arrays: per-patch Float32Arrays of one curvature; opts: { scale, percentile (50..100),
 * min, max }. Returns { min, max, dataMin, dataMax, clamped (fraction outside [min, max]),
 * count, nonFinite }. An empty or constant field gives a small non-empty range around it.
 */
export function curvatureScale(arrays, { scale = 'symmetric', percentile = 98, min = -1, max = 1 } = {}) {
  const { values, nonFinite } = sortedValues(arrays);
  const count = values.length;
  const dataMin = count ? values[0] : 0;
  const dataMax = count ? values[count - 1] : 0;
  const p = Math.min(Math.max(Number(percentile) || 100, 50), 100) / 100;
  let lo, hi;
  if (scale === 'fixed') {
    lo = Number(min);
    hi = Number(max);
    if (!(Number.isFinite(lo) && Number.isFinite(hi))) [lo, hi] = [-1, 1];
    if (lo > hi) [lo, hi] = [hi, lo];
  } else if (scale === 'percentile') {
    lo = quantile(values, 1 - p);
    hi = quantile(values, p);
  } else {
    const abs = Float64Array.from(values, Math.abs).sort();
    hi = quantile(abs, p);
    lo = -hi;
  }
  if (!(hi > lo)) {
    // A constant field (a plane: all 0): centre a tiny range on it so colours stay defined.
    const c = (lo + hi) / 2;
    const h = Math.max(Math.abs(c) * 1e-3, 1e-9);
    lo = c - h;
    hi = c + h;
  }
  let outside = 0;
  for (let i = 0; i < count; i++) if (values[i] < lo || values[i] > hi) outside++;
  return { min: lo, max: hi, dataMin, dataMax, clamped: count ? outside / count : 0, count, nonFinite };
}

/** A number for the legend: 3 significant digits, exponent form when tiny or huge. */
export function formatValue(x) {
  if (!Number.isFinite(x)) return String(x);
  if (x === 0) return '0';
  const a = Math.abs(x);
  if (a < 1e-3 || a >= 1e4) return x.toExponential(2);
  return Number(x.toPrecision(3)).toString();
}
