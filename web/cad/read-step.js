// A STEP file's faces as a scene (issue 40) through Open CASCADE's wasm build, as `pdesurf
// import` does natively (cli/import/cad_import.cpp, docs/cad-import.md): analytic faces as
// their expressions in OCCT's parametrisation, B-spline faces as NURBS as they are, any other
// surface converted by GeomConvert; the face's bounds are the patch's ranges, trims are not
// kept, a face closed in u only is swapped. This build of OCCT reads no face names (it has no
// STEPCAFControl_Reader) and no IGES. Runs where its glue may eval: in the page,
// web/cad/occt-worker.js. Bounded before the work: the file's size, the faces (counted
// before any is converted), each face's control points and degree.
import { loadOcct } from './load-occt.js';
import { CadFileError, checkFaceCount, checkFaceSize, checkFileSize, cadScene, nurbsPatch, swapsOf, uniqueName } from './cad-scene.js';

// Shortest text that reads back to x.
const num = (x) => (Object.is(x, -0) ? '0' : String(x));
const group = (e) => (e.includes(' ') ? `(${e})` : e);
// c·f ('' where c is 0, f alone where c is 1; f '' means the number c itself).
function term(c, f) {
  if (c === 0 || f === '0') return '';
  if (f === '') return num(c);
  if (c === 1) return f;
  if (c === -1) return `-${group(f)}`;
  return `${num(c)}*${group(f)}`;
}
function sum(terms) {
  let out = '';
  for (const t of terms) {
    if (!t) continue;
    if (!out) out = t;
    else if (t[0] === '-') out += ` - ${t.slice(1)}`;
    else out += ` + ${t}`;
  }
  return out || '0';
}
const xyzOf = (p) => [p.X(), p.Y(), p.Z()];

// The analytic surfaces' expressions (as cad_import.cpp's analyticExpressions): u and v name
// OCCT's u and v in the text. Null for any other type.
function analyticExpressions(oc, a, type, u, v) {
  const T = oc.GeomAbs_SurfaceType;
  const frame = (ax, radial, axial) => {
    const o = xyzOf(ax.Location()), x = xyzOf(ax.XDirection()), y = xyzOf(ax.YDirection()), z = xyzOf(ax.Direction());
    return [0, 1, 2].map((c) => {
      const around = sum([term(x[c], `cos(${u})`), term(y[c], `sin(${u})`)]);
      const radialTerm = around === '0' ? '' : radial === '1' ? around : `${group(radial)}*${group(around)}`;
      return sum([term(o[c], ''), radialTerm, term(z[c], axial)]);
    });
  };
  switch (type) {
    case T.GeomAbs_Plane: {
      const ax = a.Plane().Position();
      const o = xyzOf(ax.Location()), x = xyzOf(ax.XDirection()), y = xyzOf(ax.YDirection());
      return [0, 1, 2].map((c) => sum([term(o[c], ''), term(x[c], u), term(y[c], v)]));
    }
    case T.GeomAbs_Cylinder: {
      const s = a.Cylinder();
      return frame(s.Position(), num(s.Radius()), v);
    }
    case T.GeomAbs_Cone: {
      const s = a.Cone();
      return frame(s.Position(), sum([term(s.RefRadius(), ''), term(Math.sin(s.SemiAngle()), v)]), term(Math.cos(s.SemiAngle()), v));
    }
    case T.GeomAbs_Sphere: {
      const s = a.Sphere();
      return frame(s.Position(), term(s.Radius(), `cos(${v})`), term(s.Radius(), `sin(${v})`));
    }
    case T.GeomAbs_Torus: {
      const s = a.Torus();
      return frame(s.Position(), sum([term(s.MajorRadius(), ''), term(s.MinorRadius(), `cos(${v})`)]), term(s.MinorRadius(), `sin(${v})`));
    }
    default: return null;
  }
}

const knotsOf = (array) => Array.from({ length: array.Upper() - array.Lower() + 1 }, (_, k) => array.Value(array.Lower() + k));

function bsplinePatch(bs, name, who, [[u0, u1], [v0, v1]], swap) {
  if (bs.IsUPeriodic()) bs.SetUNotPeriodic();
  if (bs.IsVPeriodic()) bs.SetVNotPeriodic();
  const nu = bs.NbUPoles(), nv = bs.NbVPoles();
  checkFaceSize(who, nu, nv, bs.UDegree(), bs.VDegree()); // before the points are read
  const rows = [], weights = [];
  for (let i = 1; i <= nu; i++) {
    const row = [], wrow = [];
    for (let j = 1; j <= nv; j++) row.push(xyzOf(bs.Pole(i, j))), wrow.push(bs.Weight(i, j));
    rows.push(row), weights.push(wrow);
  }
  const ku = knotsOf(bs.UKnotSequence()), kv = knotsOf(bs.VKnotSequence());
  const p = bs.UDegree(), q = bs.VDegree();
  // The face's bounds within the surface's domain (equal, up to rounding).
  const domain = [[Math.max(u0, ku[p]), Math.min(u1, ku[nu])], [Math.max(v0, kv[q]), Math.min(v1, kv[nv])]];
  if (!(domain[0][1] > domain[0][0] && domain[1][1] > domain[1][0])) throw new CadFileError('InvalidField', `${who}: its bounds lie outside its surface`);
  return nurbsPatch(name, who, { degree: [p, q], knots: [ku, kv], rows, weights, domain, swap });
}

/**
 * The bytes of a STEP file -> a scene { format, version 4, title, description, patches };
 * throws CadFileError. `fileName` titles it; onLoadProgress(loadedBytes, totalBytes) is told as
 * Open CASCADE's wasm arrives, on its first load.
 */
export async function readStep(bytes, { fileName = 'the file', loadOpenCascade = loadOcct, onLoadProgress = null } = {}) {
  checkFileSize(bytes.byteLength);
  const oc = await loadOpenCascade({ onProgress: onLoadProgress });
  const path = '/import.step';
  oc.FS.writeFile(path, bytes instanceof Uint8Array ? bytes : new Uint8Array(bytes));
  const reader = new oc.STEPControl_Reader();
  const owned = [reader];
  try {
    let status;
    try {
      status = reader.ReadFile(path);
    } catch {
      status = null;
    }
    if (status !== oc.IFSelect_ReturnStatus.IFSelect_RetDone) throw new CadFileError('ParseError', 'Open CASCADE could not read it as STEP');
    reader.TransferRoots(new oc.Message_ProgressRange());
    const shape = reader.OneShape();
    owned.push(shape);
    const faces = [];
    const explorer = new oc.TopExp_Explorer(shape, oc.TopAbs_ShapeEnum.TopAbs_FACE, oc.TopAbs_ShapeEnum.TopAbs_SHAPE);
    owned.push(explorer);
    // Counted before any face is converted: a scene holds 64 patches.
    for (; explorer.More(); explorer.Next()) {
      faces.push(oc.TopoDS.Face(explorer.Current()));
      if (faces.length > 64) break;
    }
    checkFaceCount(faces.length);
    const taken = new Set();
    const patches = faces.map((face, k) => {
      const name = uniqueName('', k, taken);
      const who = `face '${name}' (${k + 1} of ${faces.length})`;
      const a = new oc.BRepAdaptor_Surface(face, true);
      owned.push(a);
      const domain = [[a.FirstUParameter(), a.LastUParameter()], [a.FirstVParameter(), a.LastVParameter()]];
      if (!domain.flat().every((x) => Number.isFinite(x) && Math.abs(x) <= 1e12)) throw new CadFileError('NonFinite', `${who}: its parameter bounds are not finite`);
      if (!(domain[0][1] > domain[0][0] && domain[1][1] > domain[1][0])) throw new CadFileError('InvalidField', `${who}: its parameter bounds are empty`);
      const swap = swapsOf((u, v) => xyzOf(a.Value(u, v)), domain);
      const type = a.GetType();
      const xyz = analyticExpressions(oc, a, type, swap ? 'v' : 't', swap ? 't' : 'v');
      if (xyz) return { name, kind: 'surface', x: xyz[0], y: xyz[1], z: xyz[2], t_range: domain[swap ? 1 : 0], v_range: domain[swap ? 0 : 1] };
      let bs;
      try {
        bs = type === oc.GeomAbs_SurfaceType.GeomAbs_BSplineSurface ? a.BSpline() : oc.GeomConvert.SurfaceToBSplineSurface(oc.BRep_Tool.Surface(face));
      } catch {
        bs = null;
      }
      if (!bs) throw new CadFileError('InvalidField', `${who}: Open CASCADE could not convert its surface to a B-spline`);
      return bsplinePatch(bs.get ? bs.get() : bs, name, who, domain, swap);
    });
    return cadScene(fileName, patches);
  } finally {
    for (const o of owned) o.delete?.();
    try {
      oc.FS.unlink(path);
    } catch {
      // already gone
    }
  }
}
