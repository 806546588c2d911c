// Fitted B-spline surfaces written as a Rhino .3dm file through rhino3dm (openNURBS in
// wasm), loaded on first use only (load-rhino3dm.js). rhino3dm's glue needs eval, which the
// page's CSP refuses: in the page this runs in web/cad/rhino-worker.js.
import { checkSurface, openNurbsKnots } from './bspline-surface.js';
import { loadRhino3dm } from './load-rhino3dm.js';

/**
 * The bytes of a .3dm file, in millimetres, with model absolute tolerance `tolerance`.
 * surfaces: [{ name, degreeU, degreeV, countU, countV, knotsU, knotsV, poles, deviation, ... }]
 * (bspline-surface.js). breps (the module's exportCad with format '3dm'): each body joined,
 * [{ closed, faces (indices into surfaces), data (an openNURBS Brep's archive bytes) }], with
 * archive { archive3dm, opennurbs } (the versions they are written for): the file then holds
 * one Brep per body, its faces sharing their edges (rhino3dm's JavaScript API cannot join
 * surfaces itself). Without breps, one NurbsSurface object per surface. closedV and degenerate
 * need no writing: openNURBS finds the seam and the collapsed borders in the poles. title: kept
 * as the document string "title" (rhino3dm has no binding for openNURBS's notes).
 */
export async function write3dm(surfaces, { tolerance, title, breps, archive, loadRhino = loadRhino3dm } = {}) {
  if (!(tolerance > 0 && Number.isFinite(tolerance))) throw new TypeError(`tolerance ${tolerance}: a positive number needed`);
  // Checked before rhino3dm is loaded: bad input costs no 2.7 MB download.
  for (const s of surfaces) checkSurface(s);
  if (breps) checkBreps(breps, surfaces.length, archive);
  const rh = await loadRhino();
  const file = new rh.File3dm();
  try {
    const settings = file.settings();
    settings.modelAbsoluteTolerance = tolerance;
    settings.modelUnitSystem = rh.UnitSystem.Millimeters;
    file.applicationName = 'pdesurf';
    if (title) file.strings().set('title', String(title));
    if (breps) breps.forEach((b, k) => addBrep(rh, file, b, bodyName(title, surfaces, b, k, breps.length), surfaces, archive));
    else for (const s of surfaces) addSurface(rh, file, s);
    // A copy: a view into the wasm heap would go stale when the heap grows.
    return new Uint8Array(file.toByteArray());
  } finally {
    file.delete();
  }
}

function checkBreps(breps, faceCount, archive) {
  if (!Array.isArray(breps)) throw new TypeError('breps: an array needed');
  if (!Number.isInteger(archive?.archive3dm) || !Number.isFinite(archive?.opennurbs)) throw new TypeError('archive: { archive3dm, opennurbs } needed with breps');
  breps.forEach((b, k) => {
    if (!(b?.data instanceof Uint8Array) || b.data.length === 0) throw new TypeError(`body ${k + 1}: no Brep bytes`);
    if (!Array.isArray(b.faces) || !b.faces.every((f) => Number.isInteger(f) && f >= 0 && f < faceCount)) throw new TypeError(`body ${k + 1}: faces must index the surfaces`);
  });
}

// A body is named after the model (one body) or numbered; its faces' names go with it.
function bodyName(title, surfaces, b, k, count) {
  const base = title || (b.faces.length === 1 ? surfaces[b.faces[0]].name : 'body');
  return count === 1 ? base : `${base} ${k + 1}`;
}

function base64(bytes) {
  let text = '';
  for (let at = 0; at < bytes.length; at += 0x8000) text += String.fromCharCode(...bytes.subarray(at, at + 0x8000));
  return btoa(text);
}

function addBrep(rh, file, b, name, surfaces, archive) {
  // decode reads the opennurbs version as a 32-bit int: the unsigned number wraps, as encode() writes it.
  const brep = rh.CommonObject.decode({ version: 10000, archive3dm: archive.archive3dm, opennurbs: archive.opennurbs | 0, data: base64(b.data) });
  if (!brep) throw new Error(`${name}: rhino3dm could not read the body's Brep`);
  const attributes = new rh.ObjectAttributes();
  try {
    const [valid, log] = brep.isValidWithLog;
    if (!valid) throw new Error(`${name}: rhino3dm finds the Brep invalid: ${String(log).trim().split('\n').slice(0, 3).join(' ')}`);
    attributes.name = name;
    const faces = b.faces.map((f) => surfaces[f]);
    attributes.setUserString('pdesurf.faces', faces.map((s) => s.name).join(', '));
    // The certified bound on |fit - exact| over the body's faces, for whoever reads the file after us.
    const deviations = faces.map((s) => s.deviation).filter(Number.isFinite);
    if (deviations.length) attributes.setUserString('pdesurf.deviation', String(Math.max(...deviations)));
    file.objects().add(brep, attributes); // adds a copy
  } finally {
    attributes.delete();
    brep.delete();
  }
}

function addSurface(rh, file, s) {
  const srf = rh.NurbsSurface.create(3, false, s.degreeU + 1, s.degreeV + 1, s.countU, s.countV);
  const attributes = new rh.ObjectAttributes();
  try {
    setKnots(srf.knotsU(), openNurbsKnots(s.knotsU));
    setKnots(srf.knotsV(), openNurbsKnots(s.knotsV));
    const points = srf.points();
    for (let i = 0; i < s.countU; i++) {
      for (let j = 0; j < s.countV; j++) {
        const at = (i * s.countV + j) * 3;
        points.set(i, j, [s.poles[at], s.poles[at + 1], s.poles[at + 2], 1]); // (x, y, z, w): w = 1, non-rational
      }
    }
    attributes.name = s.name;
    // The certified bound on |fit - exact|, for whoever reads the file after us.
    if (Number.isFinite(s.deviation)) attributes.setUserString('pdesurf.deviation', String(s.deviation));
    file.objects().add(srf, attributes); // adds a copy
  } finally {
    attributes.delete();
    srf.delete();
  }
}

function setKnots(list, knots) {
  for (let k = 0; k < knots.length; k++) list.set(k, knots[k]);
}
