// A Rhino .3dm file's surfaces as a scene (issue 40), through rhino3dm (openNURBS in wasm): one
// "surface" patch per face of each Brep (and of each extrusion or surface object), given as
// NURBS (docs/cad-import.md), as `pdesurf import` does for STEP and IGES: the face's domain is
// the patch's ranges, trims are not kept, a face closed in u only is swapped (pdesurf's v runs
// around), names from the objects' names. Runs where rhino3dm may (its embind glue needs eval:
// in the page, web/cad/rhino-worker.js). Bounded before the work: the file's size, the faces
// (counted before any is converted), each face's control points and degree.
import { loadRhino3dm } from './load-rhino3dm.js';
import { CadFileError, MAX_PATCHES, checkFaceSize, checkFileSize, cadScene, nurbsPatch, swapsOf, uniqueName } from './cad-scene.js';

export { CadFileError };
export { MAX_CAD_FILE_BYTES } from './cad-scene.js';

// The surfaces an object holds: a Brep's faces, an extrusion's (as a Brep), a surface itself.
function facesOf(geometry) {
  if (!geometry) return [];
  if (typeof geometry.faces === 'function') {
    const list = geometry.faces();
    return Array.from({ length: list.count }, (_, k) => list.get(k));
  }
  if (typeof geometry.toBrep === 'function' && (typeof geometry.toNurbsSurface !== 'function' || geometry.constructor?.name === 'Extrusion')) {
    return facesOf(geometry.toBrep(true));
  }
  if (typeof geometry.toNurbsSurface === 'function' && typeof geometry.pointAt === 'function') return [geometry];
  return [];
}

// openNURBS keeps n + p - 1 knots (the full vector without its first and last).
const fullKnots = (list) => {
  const k = list.toList();
  return [k[0], ...k, k[k.length - 1]];
};

/** One face (a BrepFace or a Surface) -> a "surface" patch, or throws CadFileError naming it. */
function patchOf(face, name, who) {
  const surface = typeof face.underlyingSurface === 'function' ? face.underlyingSurface() : face;
  const nurbs = surface.toNurbsSurface();
  if (!nurbs) throw new CadFileError('InvalidField', `${who}: rhino3dm could not give its surface as NURBS`);
  const points = nurbs.points();
  const nu = points.countU, nv = points.countV;
  checkFaceSize(who, nu, nv, nurbs.degree(0), nurbs.degree(1)); // before the points are read
  const rows = [], weights = [];
  for (let i = 0; i < nu; i++) {
    const row = [], wrow = [];
    for (let j = 0; j < nv; j++) {
      const h = points.get(i, j); // homogeneous: [x w, y w, z w, w]
      const w = nurbs.isRational ? h[3] : 1;
      row.push([h[0] / w, h[1] / w, h[2] / w]), wrow.push(w);
    }
    rows.push(row), weights.push(wrow);
  }
  const domain = [nurbs.domain(0), nurbs.domain(1)];
  const swap = swapsOf((u, v) => nurbs.pointAt(u, v), domain);
  return nurbsPatch(name, who, {
    degree: [nurbs.degree(0), nurbs.degree(1)], knots: [fullKnots(nurbs.knotsU()), fullKnots(nurbs.knotsV())],
    rows, weights: nurbs.isRational ? weights : null, domain, swap,
  });
}

/**
 * The bytes of a .3dm file -> a scene { format, version 4, title, description, patches };
 * throws CadFileError. `fileName` titles it.
 */
export async function read3dm(bytes, { fileName = 'the file', loadRhino = loadRhino3dm } = {}) {
  checkFileSize(bytes.byteLength);
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
    return cadScene(fileName, patches, skipped ? ` ${skipped} objects that are not surfaces were left out.` : '');
  } finally {
    file.delete?.();
  }
}
