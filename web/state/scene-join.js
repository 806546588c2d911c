// Joining patches: a PDE blend between two picked borders (ends by reference to a surface,
// docs/blends-by-reference.md, or continuing a pde patch's end or a Bézier border, a chain), a
// Bézier fill bounded by four picked surface borders (the version-4 `borders` field) and a PDE
// fill of a loop of 1 to 8 borders of any kind (docs/chains-and-fills.md). A pick is
// { surface, at }: `surface` names the patch the border belongs to (a surface, a pde patch or a
// Bézier patch) and `at` the border (t0/t1, u0/u1, u0/u1/v0/v1). All validate everything
// first, then change the scene.
import { isObject, patchesOf, findPatch, checkNewPatchName, uniquePatchName } from './patch-names.js';
import { checkExpression, numberField, namesIn } from './expr-text.js';
import { CONTINUITIES, ISO_LINES } from './ends-edit.js';
import { kindInfo, isSurfaceKind } from './patch-kinds.js';

const DEFAULT_V_RANGE = [0, '2*pi'];
const EDGES = ['v0', 'u1', 'v1', 'u0'];

function raiseVersion(scene) {
  if (scene.version === 1) throw new Error('version: a version-1 scene cannot name surfaces; use version 2 or later');
  if (!(scene.version >= 4)) scene.version = 4;
}

/** The "surface" patch a pick names; throws naming the field `path`. */
function surfaceOf(scene, name, path) {
  const p = findPatch(scene, name);
  if (!p) throw new Error(`${path}.surface: there is no patch named ${JSON.stringify(String(name))}`);
  if (p.kind !== 'surface') throw new Error(`${path}.surface: ${JSON.stringify(name)} is a ${p.kind} patch; only "surface" patches can be met`);
  return p;
}

const vRangeOf = (p) => (Array.isArray(p.v_range) ? p.v_range : DEFAULT_V_RANGE);


/** The borders a patch offers to blends and fills: a surface's t0/t1, a pde patch's ends, a Bézier patch's four edges; a fill none. */
export function bordersOfPatch(p) {
  return isObject(p) ? kindInfo(p.kind).borders : [];
}

/** The patch a pick names and its border, checked: throws naming `path`. */
function borderOf(scene, pick, path) {
  if (!isObject(pick)) throw new Error(`${path}: expected { surface, at }`);
  const p = findPatch(scene, pick.surface);
  if (!p) throw new Error(`${path}.surface: there is no patch named ${JSON.stringify(String(pick.surface))}`);
  if (p.kind === 'fill') throw new Error(`${path}.surface: ${JSON.stringify(p.name)} is a fill: its border belongs to the patches it closes`);
  const offered = bordersOfPatch(p);
  if (!offered.includes(pick.at)) {
    const what = p.kind === 'pde' ? 'a pde patch: its ends are' : p.kind === 'bezier' ? 'a Bézier patch: its borders are' : 'a surface: its borders are';
    throw new Error(`${path}.at: ${JSON.stringify(p.name)} is ${what} ${offered.join(', ')}, not ${JSON.stringify(pick.at)}`);
  }
  return p;
}
const squeeze = (x) => String(x).replace(/\s+/g, '');

/** Same v_range: the same texts, or the same numbers when neither uses a parameter (which a slider could move apart). */
function sameRange(scene, ra, rb) {
  if (ra.every((x, k) => squeeze(x) === squeeze(rb[k]))) return true;
  const constant = (x) => [...namesIn(String(x))].every((n) => n === 'pi' || n === 'e');
  if (![...ra, ...rb].every(constant)) return false;
  return ra.every((x, k) => {
    const a = numberField(scene, x, 'v_range'), b = numberField(scene, rb[k], 'v_range');
    return Math.abs(a - b) <= 1e-12 * Math.max(1, Math.abs(a));
  });
}

/** A pick's `at`, checked: 't0' | 't1' | { t, replaces }. */
function checkAt(scene, at, path) {
  if (ISO_LINES.includes(at)) return at;
  if (isObject(at)) {
    checkExpression(scene, at.t, ['v'], `${path}.at.t`);
    const replaces = at.replaces ?? 't0';
    if (!ISO_LINES.includes(replaces)) throw new Error(`${path}.at.replaces: must be t0 or t1, not ${JSON.stringify(replaces)}`);
    return { t: String(at.t), replaces };
  }
  throw new Error(`${path}.at: must be "t0", "t1" or { t, replaces }, not ${JSON.stringify(at)}`);
}

// Every end by reference in the scene, as { surface, border, curve, where }.
export function existingEnds(scene) {
  const out = [];
  for (const p of patchesOf(scene)) {
    if (!isObject(p) || p.kind !== 'pde' || !isObject(p.ends)) continue;
    for (const end of ['u0', 'u1']) {
      const e = p.ends[end];
      if (!isObject(e)) continue;
      const curve = isObject(e.at);
      out.push({ surface: e.surface, border: curve ? (e.at.replaces ?? 't0') : e.at, curve, where: `${p.name}.${end}` });
    }
  }
  return out;
}

/** The core's rules between ends (one curve per surface; a replaced border is met by nobody else; a border by one end). */
export function checkEndRules(ends) {
  for (let i = 0; i < ends.length; i++) {
    for (let k = 0; k < i; k++) {
      const a = ends[i], b = ends[k];
      if (a.surface !== b.surface) continue;
      if (a.curve && b.curve) throw new Error(`${a.where}.at: ${JSON.stringify(a.surface)} is already trimmed along a curve by ${b.where}; a surface can be trimmed along one curve only`);
      if ((a.curve || b.curve) && a.border === b.border) throw new Error(`${a.where}.at: ${a.border} of ${JSON.stringify(a.surface)} is replaced by a curve at ${(a.curve ? a : b).where}, and ${(a.curve ? b : a).where} meets it`);
      // Two ends on one border: three sheets would meet along it (the core refuses it too).
      if (!a.curve && !b.curve && a.border === b.border) throw new Error(`${a.where}.at: ${a.border} of ${JSON.stringify(a.surface)} is already met by ${b.where}: three sheets would meet along it`);
    }
  }
}

function endField(scene, pick, opts, path) {
  if (!isObject(pick)) throw new Error(`${path}: expected { surface, at }`);
  const p = findPatch(scene, pick.surface);
  if (p && (p.kind === 'pde' || p.kind === 'bezier')) return chainField(scene, pick, opts, path);
  surfaceOf(scene, pick.surface, path);
  const at = checkAt(scene, pick.at, path);
  const continuity = pick.continuity ?? opts.continuity ?? 'tangency';
  if (!CONTINUITIES.includes(continuity)) throw new Error(`${path}.continuity: must be ${CONTINUITIES.join(', ')}, not ${JSON.stringify(continuity)}`);
  const power = pick.power ?? opts.power ?? 1;
  if (typeof power === 'number') numberField(scene, power, `${path}.power`);
  else checkExpression(scene, power, ['v'], `${path}.power`);
  const flip = pick.flip ?? opts.flip ?? false;
  if (typeof flip !== 'boolean') throw new Error(`${path}.flip: must be true or false`);
  const out = { surface: pick.surface, at, continuity, power };
  if (flip) out.flip = true;
  return out;
}

/** An end continuing a pde patch's end or a Bézier border (a chain): its power is a number. */
function chainField(scene, pick, opts, path) {
  borderOf(scene, pick, path);
  const continuity = pick.continuity ?? opts.continuity ?? 'tangency';
  if (!CONTINUITIES.includes(continuity)) throw new Error(`${path}.continuity: must be ${CONTINUITIES.join(', ')}, not ${JSON.stringify(continuity)}`);
  const power = pick.power ?? opts.power ?? 1;
  if (typeof power !== 'number') throw new Error(`${path}.power: an end on a patch takes a number`);
  const value = numberField(scene, power, `${path}.power`);
  if (!(value > 0)) throw new Error(`${path}.power: must be positive`);
  // The solver's bound (cpp/common/limits.hpp kEndScale): past it a spike, and p² overflows.
  if (!(value <= 100)) throw new Error(`${path}.power: at most 100`);
  return { patch: pick.surface, at: pick.at, continuity, power };
}

/**
 * The blend's v_range: a chain shares v with the pde patch it continues, an end by reference
 * lies on its surface's v (both the same range); a Bézier border's [0, 1] runs over the
 * blend's v_range, which is then the other end's (or [0, 1]).
 */
function blendRange(scene, u0, u1) {
  const rangeOf = (e) => {
    if (e.surface !== undefined) return vRangeOf(findPatch(scene, e.surface));
    const p = findPatch(scene, e.patch);
    return p.kind === 'pde' ? vRangeOf(p) : null;
  };
  const [ra, rb] = [rangeOf(u0), rangeOf(u1)];
  const label = (e) => JSON.stringify(e.surface ?? e.patch);
  if (ra && rb && !sameRange(scene, ra, rb)) {
    throw new Error(`v_range: ${label(u0)} has v in ${JSON.stringify(ra)} and ${label(u1)} in ${JSON.stringify(rb)}; a blend shares v with both, so they must be the same`);
  }
  return [...(ra ?? rb ?? [0, 1])];
}

/**
 * Add a PDE blend from border `a` (its u0) to border `b` (its u1), each
 * { surface, at: 't0' | 't1' | { t, replaces } } (optionally its own continuity, power, flip).
 * options: { continuity: 'tangency', power: 1, flip: false, name }. The blend's v_range is
 * the surfaces' common one; no operator: the solver infers its order from the continuities.
 * Returns the blend's name.
 */
export function addBlend(scene, a, b, options = {}) {
  const u0 = endField(scene, a, options, 'u0');
  const u1 = endField(scene, b, options, 'u1');
  const border = (e) => (isObject(e.at) ? e.at.replaces : e.at);
  const owner = (e) => e.surface ?? e.patch;
  if (owner(u0) === owner(u1) && border(u0) === border(u1)) {
    throw new Error(`u1.at: both ends meet ${border(u0)} of ${JSON.stringify(owner(u0))}: the blend would start and end on the same curve`);
  }
  const range = blendRange(scene, u0, u1);
  const name = options.name ?? uniquePatchName(scene, 'blend');
  checkNewPatchName(scene, name);
  const mine = [u0, u1].filter((e) => e.surface !== undefined)
    .map((e) => ({ surface: e.surface, border: border(e), curve: isObject(e.at), where: `${name}.${e === u0 ? 'u0' : 'u1'}` }));
  checkEndRules([...existingEnds(scene), ...mine]);
  raiseVersion(scene);
  scene.patches.push({ name, kind: 'pde', v_range: range, ends: { u0, u1 } });
  return name;
}

const dist = (p, q) => Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);

function checkPoint(p, path) {
  if (!Array.isArray(p) || p.length !== 3 || !p.every(Number.isFinite)) throw new Error(`${path}: expected a point [x, y, z] of finite numbers`);
}

/**
 * Picked borders of a fill, each once, each with its two drawn ends: a Bézier fill's are
 * "surface" patches' t0/t1 (its rings of control points are derived from them); a PDE fill
 * takes any patch's border (`anyKind`).
 */
function checkPicks(scene, borders, endpoints, anyKind = false) {
  const seen = new Set();
  borders.forEach((b, k) => {
    if (!isObject(b)) throw new Error(`borders[${k}]: expected { surface, at }`);
    if (anyKind) borderOf(scene, b, `borders[${k}]`);
    else {
      const p = findPatch(scene, b.surface);
      if (p && !isSurfaceKind(p.kind)) throw new Error(`borders[${k}].surface: ${JSON.stringify(p.name)} is a ${p.kind} patch; a Bézier fill's borders lie on "surface" patches (a PDE fill takes any border)`);
      surfaceOf(scene, b.surface, `borders[${k}]`);
      if (!ISO_LINES.includes(b.at)) throw new Error(`borders[${k}].at: must be "t0" or "t1", not ${JSON.stringify(b.at)}`);
    }
    const key = JSON.stringify([b.surface, b.at]);
    if (seen.has(key)) throw new Error(`borders[${k}]: ${b.at} of ${JSON.stringify(b.surface)} is picked twice`);
    seen.add(key);
    if (!Array.isArray(endpoints[k]) || endpoints[k].length !== 2) throw new Error(`endpoints[${k}]: expected [start, end]`);
    endpoints[k].forEach((p, e) => checkPoint(p, `endpoints[${k}][${e}]`));
  });
}

/** The diagonal of the picked borders' ends' bounding box (the loop's size, for tolerances). */
function loopSize(endpoints) {
  const all = endpoints.flat();
  return Math.hypot(...[0, 1, 2].map((c) => Math.max(...all.map((p) => p[c])) - Math.min(...all.map((p) => p[c]))));
}

/**
 * Which way round four borders go: borders[k]'s drawn ends are endpoints[k] = [start, end]
 * (at the surface's v0 and v1). Returns [{ index, forward }] in loop order, starting with
 * borders[0] forward; throws when they do not close into a loop within `tol`.
 */
const COUNT_WORDS = ['no', 'one', 'two', 'three', 'four', 'five', 'six'];

export function chainBorders(endpoints, tol) {
  const n = endpoints.length;
  const count = COUNT_WORDS[n] ?? String(n);
  const order = [{ index: 0, forward: true }];
  const left = new Set(endpoints.map((_, k) => k).slice(1));
  let at = endpoints[0][1];
  for (let step = 1; step < n; step++) {
    let best = null;
    for (const k of left) {
      for (const forward of [true, false]) {
        const d = dist(at, endpoints[k][forward ? 0 : 1]);
        if (!best || d < best.d) best = { k, forward, d };
      }
    }
    if (best.d > tol) throw new Error(`borders: the ${count} borders do not form a closed loop: no border starts where border ${order[step - 1].index} ends (nearest ${best.d.toPrecision(3)} away, tolerance ${tol.toPrecision(3)})`);
    order.push({ index: best.k, forward: best.forward });
    left.delete(best.k);
    at = endpoints[best.k][best.forward ? 1 : 0];
  }
  const gap = dist(at, endpoints[0][0]);
  if (gap > tol) throw new Error(`borders: the ${count} borders do not close: the last ends ${gap.toPrecision(3)} from where the first starts (tolerance ${tol.toPrecision(3)})`);
  return order;
}

/**
 * Add a Bézier fill bounded by four picked borders ({ surface, at: 't0' | 't1' }, in any
 * order). endpoints[k] = [[x, y, z] at v0, [x, y, z] at v1]: where the page draws picked
 * border k's ends. The fill's edges v0, u1, v1, u0 go round the loop (borders[0] is v0,
 * forward), each edge's `reverse` chosen so that consecutive borders meet corner to corner.
 * options: { degree: [7, 7], energy: 'thin-plate', tolerance (default 1e-3 of the loop's
 * size), name }. Returns the fill's name.
 */
export function addFill(scene, borders, endpoints, options = {}) {
  if (!Array.isArray(borders) || borders.length !== 4) throw new Error('borders: expected four borders');
  if (!Array.isArray(endpoints) || endpoints.length !== 4) throw new Error('endpoints: expected the two ends of each of the four borders');
  checkPicks(scene, borders, endpoints);
  const energy = options.energy ?? 'thin-plate';
  if (energy !== 'thin-plate' && energy !== 'membrane') throw new Error(`energy: must be "thin-plate" or "membrane", not ${JSON.stringify(energy)}`);
  const degree = options.degree ?? [7, 7];
  if (!Array.isArray(degree) || degree.length !== 2 || !degree.every((d) => Number.isInteger(d) && d >= 1 && d <= 16)) {
    throw new Error(`degree: expected [n, m], integers from 1 to 16, not ${JSON.stringify(degree)}`);
  }
  const tol = options.tolerance ?? 1e-3 * loopSize(endpoints);
  endpoints.forEach(([p, q], k) => {
    if (dist(p, q) <= tol) throw new Error(`borders[${k}]: ${borders[k].at} of ${JSON.stringify(borders[k].surface)} is closed (its ends meet); a fill needs four open borders`);
  });
  const loop = chainBorders(endpoints, tol);
  const name = options.name ?? uniquePatchName(scene, 'fill');
  checkNewPatchName(scene, name);
  raiseVersion(scene);
  // v0 and u1 run along the loop, v1 and u0 against it (v1 runs from u0's end to u1's end).
  const out = {};
  loop.forEach(({ index, forward }, k) => {
    const alongLoop = k < 2;
    out[EDGES[k]] = { surface: borders[index].surface, at: borders[index].at, reverse: alongLoop ? !forward : forward };
  });
  scene.patches.push({
    name, kind: 'bezier', energy, degree: [...degree],
    borders: { v0: out.v0, u1: out.u1, v1: out.v1, u0: out.u0 },
    // No guiding normals (version 4, λ = 0): the fill is the energy's, between its borders.
  });
  return name;
}

/**
 * Add a PDE fill (kind "fill", docs/chains-and-fills.md) closing a loop of 1 to 8 picked
 * borders ({ surface, at }: a surface's t0/t1, a pde patch's u0/u1 or a Bézier border, in any
 * order; one border must be a closed curve),
 * G1 to each with a regular centre. endpoints[k] = [start, end] as for addFill; the loop's
 * order and each border's direction are found from them. options: { continuity: 'tangency'
 * (or 'position', 'curvature'), tolerance, name }. Returns the fill's name.
 */
export function addLoopFill(scene, borders, endpoints, options = {}) {
  if (!Array.isArray(borders) || borders.length < 1 || borders.length > 8) throw new Error('borders: expected 1 to 8 borders');
  if (!Array.isArray(endpoints) || endpoints.length !== borders.length) throw new Error('endpoints: expected the two ends of each border');
  checkPicks(scene, borders, endpoints, true);
  const continuity = options.continuity ?? 'tangency';
  if (!CONTINUITIES.includes(continuity)) throw new Error(`continuity: must be ${CONTINUITIES.join(', ')}, not ${JSON.stringify(continuity)}`);
  const tol = options.tolerance ?? 1e-3 * loopSize(endpoints);
  endpoints.forEach(([p, q], k) => {
    const closed = dist(p, q) <= tol;
    if (borders.length === 1 && !closed) throw new Error(`borders[0]: ${borders[0].at} of ${JSON.stringify(borders[0].surface)} is not closed: one border must be a closed curve`);
    if (borders.length > 1 && closed) throw new Error(`borders[${k}]: ${borders[k].at} of ${JSON.stringify(borders[k].surface)} is closed (its ends meet): fill it alone`);
  });
  const loop = borders.length === 1 ? [{ index: 0, forward: true }] : chainBorders(endpoints, tol);
  const name = options.name ?? uniquePatchName(scene, 'fill');
  checkNewPatchName(scene, name);
  raiseVersion(scene);
  const fill = { name, kind: 'fill', borders: loop.map(({ index, forward }) => ({ patch: borders[index].surface, at: borders[index].at, ...(forward ? {} : { reverse: true }) })) };
  if (continuity !== 'tangency') fill.continuity = continuity;
  scene.patches.push(fill);
  return name;
}
