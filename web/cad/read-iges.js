// An IGES file's B-spline surfaces as a scene (issue 40), read in plain JavaScript: the page's
// Open CASCADE build reads no IGES, and the one npm build that does is a 66 MB wasm. IGES 5.3
// gives every B-spline surface as entity 128 (what pdesurf and most CAD systems write); this
// reader takes those, with their transformation matrices (124) and the file's unit (made mm,
// as Open CASCADE reads them for `pdesurf import`). Faces are the surfaces the file's faces
// (510), trimmed (144) and bounded (143) surfaces stand on, else every independent 128; a face
// on another kind of surface (a plane 108/190, a surface of revolution 120, …) is not read and
// is named in the scene's description (`pdesurf import` reads them). Each face spans its
// surface's parameter range (trims are not read); one closed in u only is swapped, as the CLI
// does. Names: a 510 face's label, or a 406 name property, else "face k".
// Bounded before the work: the file's size, the faces (counted before any is converted), each
// face's control points and degree (before its numbers are read).
import { CadFileError, MAX_PATCHES, cadScene, checkFaceCount, checkFaceSize, checkFileSize, nurbsPatch, swapsOf, uniqueName } from './cad-scene.js';
import { nurbsPoint } from './nurbs-point.js';

// Millimetres per unit, IGES 5.3 global field 14.
const MM_PER_UNIT = { 1: 25.4, 2: 1, 4: 304.8, 5: 1609344, 6: 1000, 7: 1e6, 8: 0.0254, 9: 0.001, 10: 10, 11: 2.54e-5 };
const SURFACE_NAMES = { 108: 'plane', 114: 'parametric spline surface', 118: 'ruled surface', 120: 'surface of revolution', 122: 'tabulated cylinder', 140: 'offset surface', 190: 'plane', 192: 'cylinder', 194: 'cone', 196: 'sphere', 198: 'torus' };
// The entities faces are read from, and where each names its surface: a face (510) and a
// trimmed surface (144) first, a bounded surface (143) second, after its type.
const SURFACE_PARAMETER = { 510: 1, 144: 1, 143: 2 };

/** The parameters of a section's text: numbers as text, Hollerith strings as { text }. */
function parameters(text, delimiter, end, where) {
  const out = [];
  let k = 0;
  for (;;) {
    while (text[k] === ' ') k++;
    const h = /^(\d+)H/.exec(text.slice(k, k + 12));
    let token;
    if (h) {
      const n = Number(h[1]);
      token = { text: text.slice(k + h[0].length, k + h[0].length + n) };
      k += h[0].length + n;
      if (token.text.length < n) throw new CadFileError('ParseError', `${where}: a string runs past the end`);
      while (text[k] === ' ') k++;
    } else {
      let j = k;
      while (j < text.length && text[j] !== delimiter && text[j] !== end) j++;
      token = text.slice(k, j).trim();
      k = j;
    }
    out.push(token);
    if (k >= text.length) throw new CadFileError('ParseError', `${where}: no record delimiter '${end}'`);
    if (text[k] === end) return out;
    k++; // the delimiter
  }
}

const numberOf = (token, where) => {
  const x = typeof token === 'string' && token !== '' ? Number(token.replace(/[dD]/, 'e')) : NaN;
  if (!Number.isFinite(x)) throw new CadFileError(token === '' || typeof token !== 'string' ? 'InvalidField' : 'NonFinite', `${where}: ${JSON.stringify(token)} is not a finite number`);
  return x;
};

/** The file's sections: global parameters, directory entries, and each entity's parameters on demand. */
function sections(text) {
  const lines = text.split(/\r?\n/).filter((l) => l.trim() !== '');
  const G = [], D = [], P = [];
  for (const line of lines) {
    const kind = line[72];
    if (kind === 'G') G.push(line.slice(0, 72));
    else if (kind === 'D') D.push(line.padEnd(80));
    else if (kind === 'P') P.push(line.padEnd(80));
    else if (kind !== 'S' && kind !== 'T') throw new CadFileError('ParseError', 'not an IGES file in fixed form (80-column records marked S, G, D, P, T)');
  }
  if (!G.length || !D.length || D.length % 2) throw new CadFileError('ParseError', 'not an IGES file: its global or directory section is missing or cut');
  const g = G.join('');
  const delimiter = g.startsWith('1H') ? g[2] : ',';
  const end = g.slice(4).startsWith('1H') ? g[6] : ';';
  const global = parameters(g, delimiter, end, 'the global section');
  const field = (line, k) => line.slice(8 * k, 8 * k + 8).trim();
  const entities = [];
  for (let k = 0; k < D.length; k += 2) {
    const a = D[k], b = D[k + 1];
    entities.push({
      de: k + 1,
      type: Number(field(a, 0)),
      pointer: Number(field(a, 1)),
      transform: Number(field(a, 6)) || 0,
      subordinate: Number(field(a, 8).padStart(8, '0').slice(2, 4)) || 0,
      lines: Number(field(b, 3)),
      form: Number(field(b, 4)) || 0,
      label: field(b, 7),
    });
  }
  const byDe = (de) => (Number.isInteger(de) && de > 0 && de % 2 === 1 ? entities[(de - 1) / 2] : undefined);
  const parsed = new Map(); // entity -> its parameters, read once
  const params = (e) => {
    if (parsed.has(e)) return parsed.get(e);
    if (!(e.pointer >= 1 && e.lines >= 1 && e.pointer + e.lines - 1 <= P.length)) {
      throw new CadFileError('ParseError', `entity ${e.type} at directory line ${e.de}: its parameters lie outside the file`);
    }
    const text = P.slice(e.pointer - 1, e.pointer - 1 + e.lines).map((l) => l.slice(0, 64)).join('');
    const p = parameters(text, delimiter, end, `entity ${e.type} at directory line ${e.de}`);
    parsed.set(e, p);
    return p;
  };
  return { global, entities, byDe, params };
}

// The 3 × 4 matrix [R | T] of a 124 chain (identity when none).
function transformOf(file, de, depth = 0) {
  const e = file.byDe(de);
  if (!de || !e) return null;
  if (e.type !== 124 || depth > 16) throw new CadFileError('InvalidField', `directory line ${de}: not a transformation matrix (124)`);
  const p = file.params(e).slice(1, 13).map((t, k) => numberOf(t, `transformation at directory line ${de}, value ${k + 1}`));
  if (p.length < 12) throw new CadFileError('InvalidField', `transformation at directory line ${de}: 12 numbers expected`);
  const m = [p.slice(0, 4), p.slice(4, 8), p.slice(8, 12)];
  const outer = transformOf(file, e.transform, depth + 1);
  if (!outer) return m;
  return outer.map((r) => [0, 1, 2, 3].map((j) => r[0] * m[0][j] + r[1] * m[1][j] + r[2] * m[2][j] + (j === 3 ? r[3] : 0)));
}

const apply = (m, [x, y, z], s) => (m ? [0, 1, 2].map((i) => s * (m[i][0] * x + m[i][1] * y + m[i][2] * z + m[i][3])) : [s * x, s * y, s * z]);

// Entity 128 as a patch: K1 K2 M1 M2 PROP1..5, knots S and T, weights and points (u fastest),
// then U0 U1 V0 V1.
function bsplinePatch(file, e, name, who, scale) {
  const t = file.params(e);
  const n = (k) => numberOf(t[k], `${who}, parameter ${k}`);
  const [K1, K2, M1, M2] = [1, 2, 3, 4].map(n);
  if (![K1, K2, M1, M2].every(Number.isInteger) || M1 < 1 || M2 < 1 || K1 < M1 || K2 < M2) {
    throw new CadFileError('InvalidField', `${who}: counts and degrees ${K1}, ${K2}, ${M1}, ${M2} are not a B-spline surface's`);
  }
  const nu = K1 + 1, nv = K2 + 1;
  checkFaceSize(who, nu, nv, M1, M2); // before its numbers are read
  const ku0 = 10, kv0 = ku0 + nu + M1 + 1, w0 = kv0 + nv + M2 + 1, p0 = w0 + nu * nv, r0 = p0 + 3 * nu * nv;
  if (t.length < r0 + 4) throw new CadFileError('InvalidField', `${who}: ${t.length - 1} parameters, ${r0 + 3} expected`);
  const range = (a, b) => Array.from({ length: b - a }, (_, k) => n(a + k));
  const ku = range(ku0, kv0), kv = range(kv0, w0);
  const m = transformOf(file, e.transform);
  const rows = [], weights = [];
  for (let i = 0; i < nu; i++) {
    const row = [], wrow = [];
    for (let j = 0; j < nv; j++) {
      const k = j * nu + i;
      row.push(apply(m, [n(p0 + 3 * k), n(p0 + 3 * k + 1), n(p0 + 3 * k + 2)], scale));
      wrow.push(n(w0 + k));
    }
    rows.push(row), weights.push(wrow);
  }
  const [U0, U1, V0, V1] = range(r0, r0 + 4);
  const domain = [[Math.max(U0, ku[M1]), Math.min(U1, ku[nu])], [Math.max(V0, kv[M2]), Math.min(V1, kv[nv])]];
  if (!(domain[0][1] > domain[0][0] && domain[1][1] > domain[1][0])) throw new CadFileError('InvalidField', `${who}: its parameter range lies outside its knots`);
  if (weights.some((r) => r.some((w) => !(w > 0)))) throw new CadFileError('InvalidField', `${who}: a weight is not positive`);
  const swap = swapsOf((u, v) => nurbsPoint({ degree: [M1, M2], knots: [ku, kv], rows, weights }, u, v), domain);
  return nurbsPatch(name, who, { degree: [M1, M2], knots: [ku, kv], rows, weights, domain, swap });
}

// How many parameters (the type number included) an entity has before its associativity and
// property pointers (IGES 5.3 section 2.2.4.5.2): those of the types faces are read from.
function ownLength(e, p) {
  const count = (k) => Number(p[k]);
  switch (e.type) {
    case 128: {
      const [K1, K2, M1, M2] = [1, 2, 3, 4].map(count);
      return 10 + (K1 + M1 + 2) + (K2 + M2 + 2) + 4 * (K1 + 1) * (K2 + 1) + 4;
    }
    case 510: return 4 + count(2);
    case 144: return 5 + count(3);
    case 143: return 4 + count(3);
    default: return p.length;
  }
}

// A face's name: a name property (406 form 15) of the face or of its surface, else the face's
// directory label, else the surface's.
function nameOf(file, entities) {
  for (const e of entities) {
    const p = file.params(e);
    const at = ownLength(e, p);
    const associativities = Number(p[at]) || 0;
    const properties = Number(p[at + 1 + associativities]) || 0;
    for (let k = 0; k < properties; k++) {
      const ref = file.byDe(Number(p[at + 2 + associativities + k]));
      if (ref?.type === 406 && ref.form === 15) {
        const name = file.params(ref)[2];
        if (name?.text) return name.text;
      }
    }
  }
  for (const e of entities) if (e.label) return e.label;
  return '';
}

/**
 * The text of an IGES file -> a scene { format, version 4, title, description, patches };
 * throws CadFileError. `fileName` titles it.
 */
export function readIges(text, { fileName = 'the file' } = {}) {
  checkFileSize(text.length);
  const file = sections(text);
  const scale = MM_PER_UNIT[Number(file.global[13])] ?? 1;
  // The faces: the surfaces faces stand on, in the file's order, each once.
  let faces = [];
  const seen = new Set();
  let bsplines = 0;
  for (const e of file.entities) {
    if (!(e.type in SURFACE_PARAMETER)) continue;
    const surface = file.byDe(Number(file.params(e)[SURFACE_PARAMETER[e.type]]));
    if (!surface) throw new CadFileError('InvalidField', `entity ${e.type} at directory line ${e.de}: its surface pointer names no entity`);
    if (seen.has(surface.de)) continue;
    seen.add(surface.de);
    faces.push({ surface, face: e });
    if (surface.type === 128 && ++bsplines > MAX_PATCHES) break; // counted, not converted: refused below
  }
  if (!faces.length) faces = file.entities.filter((e) => e.type === 128 && e.subordinate === 0).map((surface) => ({ surface, face: null }));
  const readable = faces.filter(({ surface }) => surface.type === 128);
  const skipped = faces.filter(({ surface }) => surface.type !== 128);
  const kinds = [...new Set(skipped.map(({ surface }) => `${SURFACE_NAMES[surface.type] ?? 'a surface'} (entity ${surface.type})`))];
  if (!readable.length && skipped.length) {
    throw new CadFileError('InvalidField', `its faces are on ${kinds.join(', ')}: the page reads B-spline surfaces (entity 128) only; \`pdesurf import ${fileName} -o scene.json\` reads every kind`);
  }
  checkFaceCount(readable.length);
  const taken = new Set();
  const patches = readable.map(({ surface, face }, k) => {
    // Read (its size checked first), then named: a name property is among its last parameters.
    const patch = bsplinePatch(file, surface, '', `face ${k + 1} of ${readable.length} (directory line ${surface.de})`, scale);
    patch.name = uniqueName(nameOf(file, face ? [face, surface] : [surface]), k, taken);
    return patch;
  });
  const note = skipped.length ? ` ${skipped.length} faces on ${kinds.join(', ')} not read (the page reads B-spline surfaces only; \`pdesurf import\` reads them).` : '';
  return cadScene(fileName, patches, note);
}
