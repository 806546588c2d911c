// Line-segment geometry for many arrows and for a control net, as plain Float32Arrays
// (no three.js here, so node tests can check it). One LineSegments for hundreds of
// arrows costs one draw call, where an ArrowHelper each would cost two.

export const SEGMENTS_PER_ARROW = 5; // the shaft and four barbs (a cross head reads from any side)
const HEAD = 0.28; // head length as a fraction of the arrow
const BARB = 0.12; // barb spread as a fraction of the arrow

/** Diagonal of the bounding box of a 3-per-point array. */
export function boundsDiagonal(points) {
  if (points.length < 3) return 0;
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let k = 0; k < points.length; k += 3) {
    for (let a = 0; a < 3; a++) {
      lo[a] = Math.min(lo[a], points[k + a]);
      hi[a] = Math.max(hi[a], points[k + a]);
    }
  }
  return Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

/** An arrow length that keeps neighbours apart: about the spacing of the origins. */
export function arrowLength(origins) {
  const count = origins.length / 3;
  return count > 0 ? (0.9 * boundsDiagonal(origins)) / Math.sqrt(Math.max(count, 2)) : 0;
}

// Two unit vectors perpendicular to unit d and to each other.
function perpendiculars(dx, dy, dz) {
  // Cross with the axis least aligned with d, so the result never degenerates.
  const ax = Math.abs(dx) <= Math.abs(dy) && Math.abs(dx) <= Math.abs(dz);
  const ay = !ax && Math.abs(dy) <= Math.abs(dz);
  const [ex, ey, ez] = ax ? [1, 0, 0] : ay ? [0, 1, 0] : [0, 0, 1];
  let px = dy * ez - dz * ey, py = dz * ex - dx * ez, pz = dx * ey - dy * ex;
  const pl = Math.hypot(px, py, pz);
  px /= pl; py /= pl; pz /= pl;
  return [[px, py, pz], [dy * pz - dz * py, dz * px - dx * pz, dx * py - dy * px]];
}

/**
 * Segment end points (6 numbers per segment) of arrows from origins[k] along
 * vectors[k] (normalised), each `length` long. Zero vectors give no arrow.
 */
export function arrowSegments(origins, vectors, length) {
  const count = Math.min(origins.length, vectors.length) / 3;
  const out = new Float32Array(count * SEGMENTS_PER_ARROW * 6);
  let w = 0;
  const push = (ax, ay, az, bx, by, bz) => {
    out[w++] = ax; out[w++] = ay; out[w++] = az;
    out[w++] = bx; out[w++] = by; out[w++] = bz;
  };
  for (let k = 0; k < count; k++) {
    const ox = origins[3 * k], oy = origins[3 * k + 1], oz = origins[3 * k + 2];
    const vl = Math.hypot(vectors[3 * k], vectors[3 * k + 1], vectors[3 * k + 2]);
    if (!(vl > 0)) continue;
    const dx = vectors[3 * k] / vl, dy = vectors[3 * k + 1] / vl, dz = vectors[3 * k + 2] / vl;
    const tx = ox + length * dx, ty = oy + length * dy, tz = oz + length * dz;
    push(ox, oy, oz, tx, ty, tz);
    const bx = tx - HEAD * length * dx, by = ty - HEAD * length * dy, bz = tz - HEAD * length * dz;
    for (const [px, py, pz] of perpendiculars(dx, dy, dz)) {
      for (const s of [1, -1]) {
        const f = s * BARB * length;
        push(tx, ty, tz, bx + f * px, by + f * py, bz + f * pz);
      }
    }
  }
  return w === out.length ? out : out.slice(0, w);
}

/** Index pairs of a rows×cols grid (row-major points): every row and every column polyline. */
export function gridIndices(rows, cols) {
  const out = [];
  for (let i = 0; i < rows; i++) {
    for (let j = 0; j < cols; j++) {
      const k = i * cols + j;
      if (j + 1 < cols) out.push(k, k + 1);
      if (i + 1 < rows) out.push(k, k + cols);
    }
  }
  return out;
}
