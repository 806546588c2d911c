// A point of a NURBS surface { degree: [p, q], knots: [ku, kv] (full), rows (poles along u,
// each [x, y, z]), weights (the same shape, or null) }, by de Boor in homogeneous coordinates:
// what a CAD reader needs to tell whether a face closes (cad-scene.js closesIn).

// The span k with knots[k] <= t < knots[k + 1] inside [knots[p], knots[n]] (the last non-empty one at its end).
function span(knots, p, n, t) {
  if (t >= knots[n]) {
    let k = n - 1;
    while (k > p && knots[k] === knots[k + 1]) k--;
    return k;
  }
  let k = p;
  while (k + 1 < n && knots[k + 1] <= t) k++;
  return k;
}

// de Boor on d[0..p] (homogeneous [wx, wy, wz, w]) in place; d[p] is the curve's point.
function deBoor(knots, p, k, t, d) {
  for (let r = 1; r <= p; r++) {
    for (let j = p; j >= r; j--) {
      const lo = knots[j + k - p], hi = knots[j + 1 + k - r];
      const a = (t - lo) / (hi - lo);
      for (let c = 0; c < 4; c++) d[j][c] = (1 - a) * d[j - 1][c] + a * d[j][c];
    }
  }
  return d[p];
}

/** S(u, v) as [x, y, z]. */
export function nurbsPoint({ degree: [p, q], knots: [ku, kv], rows, weights }, u, v) {
  const nu = rows.length, nv = rows[0].length;
  const su = span(ku, p, nu, u), sv = span(kv, q, nv, v);
  const column = [];
  for (let i = su - p; i <= su; i++) {
    const row = [];
    for (let j = sv - q; j <= sv; j++) {
      const w = weights ? weights[i][j] : 1;
      const [x, y, z] = rows[i][j];
      row.push([w * x, w * y, w * z, w]);
    }
    column.push(deBoor(kv, q, sv, v, row));
  }
  const [x, y, z, w] = deBoor(ku, p, su, u, column);
  return [x / w, y / w, z / w];
}
