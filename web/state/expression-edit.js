// Version-2 expression fields of a scene (docs/scene-format-v2.md): where each one
// lives, the path the solver names it by in its errors, and writing one back. Missing
// coordinates, lists and entries read as "0", exactly as the solver reads them.

export const ENDS = ['u0', 'u1'];
export const AXES = ['x', 'y', 'z'];

const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
const asText = (v) => (typeof v === 'string' ? v : typeof v === 'number' ? String(v) : '0');

/** Whether the page edits this scene's functions as text (version 2 and later). */
export function hasExpressions(scene) {
  return isObject(scene) && typeof scene.version === 'number' && scene.version >= 2;
}

/** The solver's name for a field, e.g. "patches[0].boundary.x.u0[1]" (its error prefix). */
export function boundaryPath(index, axis, end, k) {
  return `patches[${index}].boundary.${axis}.${end}[${k}]`;
}
export function forcePath(index, axis) {
  return `patches[${index}].force.${axis}`;
}
export function surfacePath(index, axis) {
  return `patches[${index}].${axis}`;
}

/** The boundary slot u0/u1[k] of one coordinate as text. */
export function boundarySlot(patch, axis, end, k) {
  const list = patch.boundary?.[axis]?.[end];
  return Array.isArray(list) ? asText(list[k]) : '0';
}

export function setBoundarySlot(patch, axis, end, k, text) {
  if (!isObject(patch.boundary)) patch.boundary = {};
  if (!isObject(patch.boundary[axis])) patch.boundary[axis] = {};
  const comp = patch.boundary[axis];
  if (!Array.isArray(comp[end])) comp[end] = [];
  while (comp[end].length < k) comp[end].push('0');
  comp[end][k] = String(text);
}

/** The force on one coordinate as text ("0" when the scene gives none). */
export function forceOf(patch, axis) {
  return isObject(patch.force) ? asText(patch.force[axis]) : '0';
}

/** An empty force field means no force: the coordinate (and an empty force) is removed. */
export function setForce(patch, axis, text) {
  const t = String(text);
  if (t.trim() === '') {
    if (isObject(patch.force)) delete patch.force[axis];
    if (isObject(patch.force) && Object.keys(patch.force).length === 0) delete patch.force;
    return;
  }
  if (!isObject(patch.force)) patch.force = {};
  patch.force[axis] = t;
}

/** A primary surface's coordinate x, y or z (expressions in t and v). */
export function surfaceCoordinate(patch, axis) {
  return asText(patch[axis]);
}

export function setSurfaceCoordinate(patch, axis, text) {
  patch[axis] = String(text);
}

export const RANGE_ENDS = [['t_range', 0, 't from'], ['t_range', 1, 't to'], ['v_range', 0, 'v from'], ['v_range', 1, 'v to']];
const DEFAULT_RANGES = { t_range: [0, 1], v_range: [0, '2*pi'] };

/** One end of a surface's t_range or v_range, as text (a number or an expression). */
export function surfaceRangeEnd(patch, key, k) {
  const range = Array.isArray(patch[key]) ? patch[key] : (nurbsDomain(patch)?.[key] ?? DEFAULT_RANGES[key]);
  return asText(range[k]);
}

/**
 * A "surface" given as NURBS (docs/scene-format-v4.md): its domain { t_range, v_range } from
 * its knots (what the core takes when the ranges are left out), else null.
 */
export function nurbsDomain(patch) {
  const n = patch?.nurbs;
  if (!n || !Array.isArray(n.degree) || !Array.isArray(n.knots) || !Array.isArray(n.points) || !Array.isArray(n.points[0])) return null;
  const counts = [n.points.length, n.points[0].length];
  const ends = (d) => [n.knots[d]?.[n.degree[d]], n.knots[d]?.[counts[d]]];
  return { t_range: ends(0), v_range: ends(1) };
}

/** What a NURBS surface is, in words, for the panel (text: it may come from a file). */
export function nurbsSummary(patch) {
  const n = patch.nurbs;
  const rows = Array.isArray(n?.points) ? n.points.length : 0, cols = Array.isArray(n?.points?.[0]) ? n.points[0].length : 0;
  const degree = Array.isArray(n?.degree) ? n.degree.join(' × ') : '?';
  return `NURBS surface: degree ${degree}, ${rows} × ${cols} control points${n?.weights ? ', rational' : ''} (its points are data, not typed)`;
}

/** Write one end of a range: a plain number stays a number (short links), else the text. */
export function setSurfaceRangeEnd(patch, key, k, text) {
  if (key !== 't_range' && key !== 'v_range') throw new Error(`no range ${JSON.stringify(key)}`);
  const range = Array.isArray(patch[key]) ? [...patch[key]] : [...(nurbsDomain(patch)?.[key] ?? DEFAULT_RANGES[key])];
  const t = String(text).trim();
  range[k] = t !== '' && Number.isFinite(Number(t)) ? Number(t) : t;
  patch[key] = range;
}
