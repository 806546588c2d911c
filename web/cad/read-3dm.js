// A Rhino .3dm file's surfaces as a scene (issue 40), through rhino3dm (openNURBS in wasm): one
// "surface" patch per face of each Brep (and of each extrusion or surface object), given as
// NURBS (docs/cad-import.md), as `pdesurf import` does for STEP and IGES: the face's domain is
// the patch's ranges, trims are not kept, a face closed in u only is swapped (pdesurf's v runs
// around), names from the objects' names. Runs where rhino3dm may (its embind glue needs eval:
// in the page, web/cad/rhino-worker.js). Bounded before the work: the file's size, the faces
// (counted before any is converted), each face's control points and degree.
import { loadRhino3dm } from './load-rhino3dm.js';

export const MAX_CAD_FILE_BYTES = 64 << 20; // as the CLI's import (cli/import/cad_import.hpp)
const MAX_PATCHES = 64; // a scene's patches (docs/limits.md)
const MAX_POINTS = 4096; // a NURBS surface's control points (cpp/common/limits.hpp kNurbsPoints)
const MAX_DEGREE = 25; // kNurbsDegree
const NAME_CHARS = 64;

export class CadFileError extends Error {
  constructor(code, message) {
    super(message);
    this.name = 'CadFileError';
    this.code = code; // the core's names: TooLarge, ParseError, InvalidField, NonFinite
  }
}

// The surfaces an object holds: a Brep's faces, an extrusion's (as a Brep), a surface itself.
function facesOf(geometry) {
  if (!geometry) return [];
  if (typeof geometry.faces === 'function') {
    const list = geometry.faces();
    return Array.from({ length: list.count }, (_, k) => list.get(k));
  }
  if (typeof geometry.toBrep === 'function' && typeof geometry.toNurbsSurface !== 'function') return facesOf(geometry.toBrep(true));
  if (typeof geometry.toBrep === 'function' && geometry.constructor?.name === 'Extrusion') return facesOf(geometry.toBrep(true));
  if (typeof geometry.toNurbsSurface === 'function' && typeof geometry.pointAt === 'function') return [geometry];
  return [];
}

function uniqueName(want, index, taken) {
  let s = String(want ?? '').replace(/[^A-Za-z0-9_. -]/g, '').trim().slice(0, NAME_CHARS - 8);
  if (!s) s = `face ${index + 1}`;
  let name = s;
  for (let k = 2; taken.has(name); k++) name = `${s} ${k}`;
  taken.add(name);
  return name;
}

// openNURBS keeps n + p - 1 knots (the full vector without its first and last).
const fullKnots = (list) => {
  const k = list.toList();
  return [k[0], ...k, k[k.length - 1]];
};

function closes(surface, dir, size) {
  const [a, b] = surface.domain(dir), other = surface.domain(1 - dir);
  let gap = 0;
  for (let k = 0; k <= 8; k++) {
    const w = other[0] + ((other[1] - other[0]) * k) / 8;
    const p = dir === 0 ? surface.pointAt(a, w) : surface.pointAt(w, a), q = dir === 0 ? surface.pointAt(b, w) : surface.pointAt(w, b);
    gap = Math.max(gap, Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]));
  }
  return gap <= 1e-9 * size;
}

/** One face (a BrepFace or a Surface) -> a "surface" patch, or throws CadFileError naming it. */
function patchOf(face, name, who) {
  const surface = typeof face.underlyingSurface === 'function' ? face.underlyingSurface() : face;
  const nurbs = surface.toNurbsSurface();
  if (!nurbs) throw new CadFileError('InvalidField', `${who}: rhino3dm could not give its surface as NURBS`);
  const points = nurbs.points();
  const nu = points.countU, nv = points.countV, p = nurbs.degree(0), q = nurbs.degree(1);
  if (nu * nv > MAX_POINTS) throw new CadFileError('TooLarge', `${who}: ${nu} × ${nv} control points: a surface has at most ${MAX_POINTS}`);
  if (p > MAX_DEGREE || q > MAX_DEGREE) throw new CadFileError('TooLarge', `${who}: degree ${Math.max(p, q)}: at most ${MAX_DEGREE}`);
  const rows = [], weights = [];
  let size = 0;
  for (let i = 0; i < nu; i++) {
    const row = [], wrow = [];
    for (let j = 0; j < nv; j++) {
      const h = points.get(i, j); // homogeneous: [x w, y w, z w, w]
      const w = nurbs.isRational ? h[3] : 1;
      const x = [h[0] / w, h[1] / w, h[2] / w];
      if (![...x, w].every(Number.isFinite)) throw new CadFileError('NonFinite', `${who}: control point (${i + 1}, ${j + 1}) is not finite`);
      size = Math.max(size, Math.hypot(...x));
      row.push(x), wrow.push(w);
    }
    rows.push(row), weights.push(wrow);
  }
  const rational = nurbs.isRational && weights.some((r) => r.some((w) => w !== weights[0][0]));
  const domain = [nurbs.domain(0), nurbs.domain(1)];
  // pdesurf's v runs around a closed surface: a face closed in u only is swapped.
  const swap = closes(nurbs, 0, Math.max(size, 1e-300)) && !closes(nurbs, 1, Math.max(size, 1e-300));
  const knots = [fullKnots(nurbs.knotsU()), fullKnots(nurbs.knotsV())];
  const transpose = (m) => m[0].map((_, j) => m.map((r) => r[j]));
  const spec = {
    degree: swap ? [q, p] : [p, q],
    knots: swap ? [knots[1], knots[0]] : knots,
    points: swap ? transpose(rows) : rows,
  };
  if (rational) spec.weights = swap ? transpose(weights) : weights;
  return { name, kind: 'surface', nurbs: spec, t_range: domain[swap ? 1 : 0], v_range: domain[swap ? 0 : 1] };
}

/**
 * The bytes of a .3dm file -> a scene { format, version 4, title, description, patches };
 * throws CadFileError. `fileName` titles it.
 */
export async function read3dm(bytes, { fileName = 'the file', loadRhino = loadRhino3dm } = {}) {
  if (bytes.byteLength > MAX_CAD_FILE_BYTES) {
    throw new CadFileError('TooLarge', `the file has ${bytes.byteLength} bytes: at most ${MAX_CAD_FILE_BYTES >> 20} MB are imported`);
  }
  const rh = await loadRhino();
  const file = rh.File3dm.fromByteArray(bytes instanceof Uint8Array ? bytes : new Uint8Array(bytes));
  if (!file) throw new CadFileError('ParseError', 'rhino3dm could not read it as a .3dm file');
  try {
    const objects = file.objects();
    const found = [];
    let skipped = 0;
    for (let k = 0; k < objects.count; k++) {
      const object = objects.get(k);
      const faces = facesOf(object.geometry());
      if (!faces.length) skipped++;
      const attributes = object.attributes();
      const objectName = attributes?.name ?? '';
      // pdesurf's own .3dm names a body's faces in its user string (web/cad/write-3dm.js).
      const listed = String(attributes?.getUserString?.('pdesurf.faces') ?? '').split(', ');
      const named = listed.length === faces.length && listed.every((n) => n.trim());
      faces.forEach((face, f) => found.push({ face, want: named ? listed[f] : objectName && faces.length > 1 ? `${objectName} ${f + 1}` : objectName }));
      // Counted while gathering, before any face is converted: a scene holds MAX_PATCHES.
      if (found.length > MAX_PATCHES) throw new CadFileError('TooLarge', `the file has more than ${MAX_PATCHES} faces: a scene holds at most ${MAX_PATCHES} patches`);
    }
    if (!found.length) throw new CadFileError('InvalidField', 'the file has no surfaces (Breps, extrusions or surface objects)');
    const taken = new Set();
    const patches = found.map(({ face, want }, k) => {
      const name = uniqueName(want, k, taken);
      return patchOf(face, name, `face '${name}' (${k + 1} of ${found.length})`);
    });
    return {
      format: 'pdesurf-scene',
      version: 4,
      title: fileName,
      description: `Imported from ${fileName}: ${patches.length} faces as NURBS surfaces over their domains (trims not kept); a face closed in u only has t and v swapped.`
        + (skipped ? ` ${skipped} objects that are not surfaces were left out.` : ''),
      patches,
    };
  } finally {
    file.delete?.();
  }
}
