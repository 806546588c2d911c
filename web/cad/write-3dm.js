// Fitted B-spline surfaces written as a Rhino .3dm file through rhino3dm (openNURBS in
// wasm), loaded on first use only (load-rhino3dm.js). rhino3dm's glue needs eval, which the
// page's CSP refuses: in the page this runs in web/cad/rhino-worker.js.
import { checkSurface, openNurbsKnots } from './bspline-surface.js';
import { loadRhino3dm } from './load-rhino3dm.js';

/**
 * The bytes of a .3dm file holding one non-rational NurbsSurface object per surface (named
 * after it), in millimetres, with model absolute tolerance `tolerance`.
 * surfaces: [{ name, degreeU, degreeV, countU, countV, knotsU, knotsV, poles, deviation, ... }]
 * (bspline-surface.js); closedV and degenerate need no writing: openNURBS finds the seam and
 * the collapsed borders in the poles. title: kept as the document string "title" (rhino3dm
 * has no binding for openNURBS's notes).
 */
export async function write3dm(surfaces, { tolerance, title, loadRhino = loadRhino3dm } = {}) {
  if (!(tolerance > 0 && Number.isFinite(tolerance))) throw new TypeError(`tolerance ${tolerance}: a positive number needed`);
  // Checked before rhino3dm is loaded: bad input costs no 2.7 MB download.
  for (const s of surfaces) checkSurface(s);
  const rh = await loadRhino();
  const file = new rh.File3dm();
  try {
    const settings = file.settings();
    settings.modelAbsoluteTolerance = tolerance;
    settings.modelUnitSystem = rh.UnitSystem.Millimeters;
    file.applicationName = 'pdesurf';
    if (title) file.strings().set('title', String(title));
    for (const s of surfaces) addSurface(rh, file, s);
    // A copy: a view into the wasm heap would go stale when the heap grows.
    return new Uint8Array(file.toByteArray());
  } finally {
    file.delete();
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
