// A reference evaluator of the surfaces write-3dm.js takes (full clamped knots, poles i along
// u), by de Boor's triangular scheme: written apart from the writer and from openNURBS, so
// agreement between the two means the file holds the surface that was given.

// The span k with knots[k] <= t < knots[k + 1], the last non-empty one at the end of the domain.
function span(knots, degree, count, t) {
  if (t >= knots[count]) return count - 1;
  let k = degree;
  while (knots[k + 1] <= t) k++;
  return k;
}

// de Boor on the points d[0..degree] (d[r] the pole span-degree+r), in place; d[degree] is S(t).
function deBoor(knots, degree, k, t, d) {
  for (let r = 1; r <= degree; r++) {
    for (let j = degree; j >= r; j--) {
      const lo = knots[j + k - degree], hi = knots[j + 1 + k - r];
      const a = (t - lo) / (hi - lo);
      for (let c = 0; c < 3; c++) d[j][c] = (1 - a) * d[j - 1][c] + a * d[j][c];
    }
  }
  return d[degree];
}

/** S(u, v) of surface s as [x, y, z]. */
export function evaluate(s, u, v) {
  const ku = span(s.knotsU, s.degreeU, s.countU, u), kv = span(s.knotsV, s.degreeV, s.countV, v);
  const column = [];
  for (let i = ku - s.degreeU; i <= ku; i++) {
    const row = [];
    for (let j = kv - s.degreeV; j <= kv; j++) {
      const at = (i * s.countV + j) * 3;
      row.push([s.poles[at], s.poles[at + 1], s.poles[at + 2]]);
    }
    column.push(deBoor(s.knotsV, s.degreeV, kv, v, row));
  }
  return [...deBoor(s.knotsU, s.degreeU, ku, u, column)];
}
