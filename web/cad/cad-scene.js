// What a CAD file's faces become in a scene, for the page's readers (read-3dm.js through
// rhino3dm, read-step.js through Open CASCADE) as for `pdesurf import` (cli/import/): the
// limits checked before the work, unique names, a NURBS patch over the face's domain, swapped
// when the face closes in u only (pdesurf's v runs around; docs/cad-import.md).
export const MAX_CAD_FILE_BYTES = 64 << 20; // as the CLI's import (cli/import/cad_import.hpp)
export const MAX_PATCHES = 64; // a scene's patches (docs/limits.md)
const MAX_POINTS = 16384; // a NURBS surface's control points (cpp/common/limits.hpp kNurbsPoints)
const MAX_DEGREE = 25; // kNurbsDegree
const NAME_CHARS = 64;

export class CadFileError extends Error {
  constructor(code, message) {
    super(message);
    this.name = 'CadFileError';
    this.code = code; // the core's names: TooLarge, ParseError, InvalidField, NonFinite
  }
}

export function checkFileSize(byteLength) {
  if (byteLength > MAX_CAD_FILE_BYTES) {
    throw new CadFileError('TooLarge', `the file has ${byteLength} bytes: at most ${MAX_CAD_FILE_BYTES >> 20} MB are imported`);
  }
}

export function checkFaceCount(count) {
  if (count > MAX_PATCHES) throw new CadFileError('TooLarge', `the file has ${count} faces: a scene holds at most ${MAX_PATCHES} patches`);
  if (count === 0) throw new CadFileError('InvalidField', 'the file has no faces');
}

/** A name the scene accepts: printable, at most 64 characters, unique in `taken` (a Set). */
export function uniqueName(want, index, taken) {
  let s = String(want ?? '').replace(/[^A-Za-z0-9_. -]/g, '').trim().slice(0, NAME_CHARS - 8);
  if (!s) s = `face ${index + 1}`;
  let name = s;
  for (let k = 2; taken.has(name); k++) name = `${s} ${k}`;
  taken.add(name);
  return name;
}

/** Whether a surface (value(u, v) -> [x, y, z]) closes in u (dir 0) or v over the box `domain`. */
export function closesIn(value, dir, [[u0, u1], [v0, v1]]) {
  const mid = value(0.5 * (u0 + u1), 0.5 * (v0 + v1));
  let size = 0, gap = 0;
  for (let k = 0; k <= 8; k++) {
    const a = dir === 0 ? value(u0, v0 + ((v1 - v0) * k) / 8) : value(u0 + ((u1 - u0) * k) / 8, v0);
    const b = dir === 0 ? value(u1, v0 + ((v1 - v0) * k) / 8) : value(u0 + ((u1 - u0) * k) / 8, v1);
    size = Math.max(size, Math.hypot(...a), Math.hypot(a[0] - mid[0], a[1] - mid[1], a[2] - mid[2]));
    gap = Math.max(gap, Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
  }
  return gap <= 1e-9 * Math.max(size, 1e-300);
}

/** Whether to swap a face's (u, v) into the patch's (v, t): closed in u only. */
export const swapsOf = (value, domain) => closesIn(value, 0, domain) && !closesIn(value, 1, domain);

const transpose = (m) => m[0].map((_, j) => m.map((r) => r[j]));

/**
 * A "surface" patch given as NURBS: `rows` of [x, y, z] (along the face's u), `weights` the
 * same shape or null, full knot vectors, ranges `domain` [[u0, u1], [v0, v1]]; swapped when
 * `swap`. Throws CadFileError (naming `who`) past the limits or for a non-finite number.
 */
/** The counts and degrees of a face, checked before its control points are read. */
export function checkFaceSize(who, nu, nv, p, q) {
  if (nu * nv > MAX_POINTS) throw new CadFileError('TooLarge', `${who}: ${nu} × ${nv} control points: a surface has at most ${MAX_POINTS}`);
  if (p > MAX_DEGREE || q > MAX_DEGREE) throw new CadFileError('TooLarge', `${who}: degree ${Math.max(p, q)}: at most ${MAX_DEGREE}`);
}

export function nurbsPatch(name, who, { degree: [p, q], knots: [ku, kv], rows, weights, domain, swap }) {
  checkFaceSize(who, rows.length, rows[0]?.length ?? 0, p, q);
  rows.forEach((row, i) => row.forEach((x, j) => {
    if (![...x, weights ? weights[i][j] : 1].every(Number.isFinite)) throw new CadFileError('NonFinite', `${who}: control point (${i + 1}, ${j + 1}) is not finite`);
  }));
  const rational = weights && weights.some((r) => r.some((w) => w !== weights[0][0]));
  const nurbs = { degree: swap ? [q, p] : [p, q], knots: swap ? [kv, ku] : [ku, kv], points: swap ? transpose(rows) : rows };
  if (rational) nurbs.weights = swap ? transpose(weights) : weights;
  return { name, kind: 'surface', nurbs, t_range: domain[swap ? 1 : 0], v_range: domain[swap ? 0 : 1] };
}

/** The scene of a file's patches. */
export function cadScene(fileName, patches, note = '') {
  return {
    format: 'pdesurf-scene',
    version: 4,
    title: fileName,
    description: `Imported from ${fileName}: ${patches.length} faces over their parameter bounds (trims not kept); a face closed in u only has t and v swapped.${note}`,
    patches,
  };
}
