// A dragged trimline, given as a few t-values along a border, as a short trigonometric sum
//   τ(v) = a0 + Σ_k a_k cos(k ω v) + b_k sin(k ω v),  ω = 2π / (v1 − v0)
// fitted by least squares and written as text, so that the blend meeting it stays in the
// closed-form families (docs/blends-by-reference.md: trigonometric trimlines split exactly).
import { numberField } from './expr-text.js';

const fmt = (x) => {
  const s = Number(x.toPrecision(6));
  return String(Object.is(s, -0) ? 0 : s);
};

// Solve the symmetric positive system A x = b (normal equations) by Gaussian elimination
// with partial pivoting; small (2K + 1 unknowns).
function solve(A, b) {
  const n = b.length;
  const M = A.map((row, i) => [...row, b[i]]);
  for (let c = 0; c < n; c++) {
    let p = c;
    for (let r = c + 1; r < n; r++) if (Math.abs(M[r][c]) > Math.abs(M[p][c])) p = r;
    [M[c], M[p]] = [M[p], M[c]];
    if (Math.abs(M[c][c]) < 1e-12) throw new Error('values: the samples do not determine the terms (too few distinct v)');
    for (let r = c + 1; r < n; r++) {
      const f = M[r][c] / M[c][c];
      for (let k = c; k <= n; k++) M[r][k] -= f * M[c][k];
    }
  }
  const x = new Array(n).fill(0);
  for (let r = n - 1; r >= 0; r--) {
    let s = M[r][n];
    for (let k = r + 1; k < n; k++) s -= M[r][k] * x[k];
    x[r] = s / M[r][r];
  }
  return x;
}

/**
 * values: t-values at equally spaced v over the period (v_k = v0 + k (v1 − v0)/N, k < N:
 * the last sample is not v1, which is v0 again), or [[v, t], ...] pairs at any v.
 * vRange: [v0, v1] (numbers or constant expressions such as "2*pi"). maxTerms: the
 * highest harmonic K (default 3), lowered to what the samples determine (2K + 1 ≤ N).
 * Returns { text, a0, a: [a1..aK], b: [b1..bK], omega } ; text has ~6 significant digits
 * and leaves out terms below 1e-6 of the largest.
 */
export function trigCurveFromSamples(values, vRange, maxTerms = 3) {
  if (!Array.isArray(values) || values.length === 0) throw new Error('values: expected t-values along the border');
  if (!Array.isArray(vRange) || vRange.length !== 2) throw new Error('vRange: expected [v0, v1]');
  const [v0, v1] = vRange.map((x, k) => numberField({}, x, `vRange[${k}]`));
  if (!(v1 > v0)) throw new Error('vRange: v1 must be greater than v0');
  if (!Number.isInteger(maxTerms) || maxTerms < 0) throw new Error('maxTerms: expected a whole number ≥ 0');
  const N = values.length;
  const pairs = values.map((x, k) => (Array.isArray(x) ? x : [v0 + (k * (v1 - v0)) / N, x]));
  pairs.forEach(([v, t], k) => {
    if (!Number.isFinite(v) || !Number.isFinite(t)) throw new Error(`values[${k}]: not a finite number`);
  });
  const omega = (2 * Math.PI) / (v1 - v0);
  const K = Math.min(maxTerms, Math.floor((N - 1) / 2));
  const basis = (v) => {
    const row = [1];
    for (let k = 1; k <= K; k++) row.push(Math.cos(k * omega * v), Math.sin(k * omega * v));
    return row;
  };
  const n = 2 * K + 1;
  const A = Array.from({ length: n }, () => new Array(n).fill(0));
  const b = new Array(n).fill(0);
  for (const [v, t] of pairs) {
    const row = basis(v);
    for (let i = 0; i < n; i++) {
      b[i] += row[i] * t;
      for (let j = 0; j < n; j++) A[i][j] += row[i] * row[j];
    }
  }
  const x = solve(A, b);
  const a0 = x[0];
  const a = [], bs = [];
  for (let k = 1; k <= K; k++) { a.push(x[2 * k - 1]); bs.push(x[2 * k]); }
  // Write the text: k ω v with ω = 1 as "k*v"; ω to 12 digits (a phase error over the range would show).
  const big = Math.max(...x.map(Math.abs));
  const arg = (k) => {
    const w = k * omega;
    if (Math.abs(w - Math.round(w)) < 1e-12) return Math.round(w) === 1 ? 'v' : `${Math.round(w)}*v`;
    return `${Number(w.toPrecision(12))}*v`;
  };
  let text = fmt(a0);
  const add = (c, f) => {
    if (Math.abs(c) <= 1e-6 * big) return;
    text += `${c < 0 ? ' - ' : ' + '}${fmt(Math.abs(c))}*${f}`;
  };
  for (let k = 1; k <= K; k++) { add(a[k - 1], `cos(${arg(k)})`); add(bs[k - 1], `sin(${arg(k)})`); }
  return { text, a0, a, b: bs, omega };
}
