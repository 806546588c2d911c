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
  const range = Array.isArray(patch[key]) ? patch[key] : DEFAULT_RANGES[key];
  return asText(range[k]);
}

/** Write one end of a range: a plain number stays a number (short links), else the text. */
export function setSurfaceRangeEnd(patch, key, k, text) {
  if (key !== 't_range' && key !== 'v_range') throw new Error(`no range ${JSON.stringify(key)}`);
  const range = Array.isArray(patch[key]) ? [...patch[key]] : [...DEFAULT_RANGES[key]];
  const t = String(text).trim();
  range[k] = t !== '' && Number.isFinite(Number(t)) ? Number(t) : t;
  patch[key] = range;
}
