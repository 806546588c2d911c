// Editing a bezier patch's initial surface S: its `control_net`, a row-major list of
// (n+1)×(m+1) points [x, y, z] (point (i, j) at i*(m+1) + j), whose entries may be
// numbers or expressions without variables. An edit writes plain numbers into the
// coordinates it changes and keeps the others as the scene had them.

export const AXES = ['x', 'y', 'z'];

const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);

/** [rows, cols] = [n+1, m+1] from the patch's degree, or null when it has none. */
export function netSizeOf(patch) {
  const d = isObject(patch) ? patch.degree : null;
  if (!Array.isArray(d) || d.length !== 2 || !d.every((n) => Number.isInteger(n) && n >= 1)) return null;
  return [d[0] + 1, d[1] + 1];
}

/**
 * How a control point of S acts on the result: the outer ring (membrane) or two rings
 * (thin plate) are fixed and copied into the surface; the others only pull through γ.
 */
export function controlPointRole(i, j, rows, cols, energy) {
  const rings = energy === 'thin-plate' ? 2 : 1;
  const fixed = i < rings || j < rings || i >= rows - rings || j >= cols - rings;
  return fixed ? 'fixed' : 'free';
}

function checkedIndex(patch, i, j) {
  const size = netSizeOf(patch);
  if (!size) throw new Error(`patch ${JSON.stringify(patch?.name)} has no degree`);
  const [rows, cols] = size;
  if (!Number.isInteger(i) || !Number.isInteger(j) || i < 0 || j < 0 || i >= rows || j >= cols) {
    throw new Error(`no control point (${i}, ${j}) in a ${rows}×${cols} net`);
  }
  const net = patch.control_net;
  const k = i * cols + j;
  if (!Array.isArray(net) || net.length !== rows * cols || !Array.isArray(net[k]) || net[k].length !== 3) {
    throw new Error(`patch ${JSON.stringify(patch.name)}: control_net does not hold ${rows}×${cols} points [x, y, z]`);
  }
  return k;
}

/** The scene's entry for one coordinate: a number, or an expression's text. */
export function controlPointEntry(patch, i, j, axis) {
  return patch.control_net[checkedIndex(patch, i, j)][AXES.indexOf(axis)];
}

/** Set one coordinate (axis x, y or z) of point (i, j) to a number. */
export function setControlPointCoordinate(patch, i, j, axis, value) {
  const a = AXES.indexOf(axis);
  if (a < 0) throw new Error(`axis must be x, y or z, not ${JSON.stringify(axis)}`);
  if (!Number.isFinite(value)) throw new Error(`a control point coordinate must be a finite number, not ${value}`);
  const k = checkedIndex(patch, i, j);
  const point = [...patch.control_net[k]];
  point[a] = value;
  patch.control_net[k] = point;
}
