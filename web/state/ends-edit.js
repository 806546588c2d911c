// One end (u0 or u1) of a blend given by reference (scene version 3,
// docs/blends-by-reference.md): reading it with the format's defaults, writing each of
// its fields, attaching a typed end to a surface and detaching a derived one back into
// typed expressions. Pure: the scene objects are changed in place; no DOM, no solver.
import { AXES, ORDERS, isPerCoordinate, perCoordinate } from './operator-edit.js';

export const ENDS = ['u0', 'u1'];
export const ISO_LINES = ['t0', 't1'];
export const TRIMLINES = [...ISO_LINES, 'curve'];
export const CONTINUITIES = ['position', 'tangency', 'curvature'];
export const SCALES = ['gap', 'surface'];
/** The operator order a continuity needs (docs/blends-by-reference.md, "Per-side continuity"). */
export const ORDER_FOR = { position: 2, tangency: 4, curvature: 6 };

const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
const asText = (v) => (typeof v === 'string' ? v : typeof v === 'number' ? String(v) : '');
const NUMBER = /^\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?\s*$/;

function checkEnd(end) {
  if (!ENDS.includes(end)) throw new Error(`end must be u0 or u1, not ${JSON.stringify(end)}`);
}

/** The scene's `ends.<end>` object, or null when that end is typed. */
export function endOf(patch, end) {
  const e = isObject(patch?.ends) ? patch.ends[end] : null;
  return isObject(e) ? e : null;
}

export const isByReference = (patch, end) => endOf(patch, end) !== null;

/** The patches an end can name: the scene's "surface" patches, in scene order. */
export function surfacePatches(scene) {
  return (Array.isArray(scene?.patches) ? scene.patches : []).filter((p) => isObject(p) && p.kind === 'surface' && typeof p.name === 'string');
}

export const surfaceNames = (scene) => surfacePatches(scene).map((p) => p.name);

/** Whether the page offers this pde patch ends by reference: it has one, or could get one. */
export function canHaveEnds(scene, patch) {
  if (!isObject(patch) || patch.kind !== 'pde') return false;
  if (ENDS.some((end) => isByReference(patch, end))) return true;
  return typeof scene?.version === 'number' && scene.version >= 2 && surfaceNames(scene).length > 0;
}

/**
 * One end as the page shows it, the format's defaults filled in:
 * { surface, trimline: 't0' | 't1' | 'curve', tau, replaces, continuity, power, scale, flip },
 * or null for a typed end.
 */
export function readEnd(patch, end) {
  const e = endOf(patch, end);
  if (!e) return null;
  const curve = isObject(e.at);
  return {
    surface: typeof e.surface === 'string' ? e.surface : '',
    trimline: curve ? 'curve' : e.at === 't1' ? 't1' : 't0',
    tau: curve ? asText(e.at.t) : '',
    replaces: curve && e.at.replaces === 't1' ? 't1' : 't0',
    continuity: CONTINUITIES.includes(e.continuity) ? e.continuity : 'tangency',
    power: typeof e.power === 'number' || typeof e.power === 'string' ? e.power : 1,
    scale: e.scale === 'surface' ? 'surface' : 'gap',
    flip: e.flip === true,
  };
}

function referenced(patch, end) {
  checkEnd(end);
  const e = endOf(patch, end);
  if (!e) throw new Error(`end ${end} of ${JSON.stringify(patch?.name)} is typed, not given by reference`);
  return e;
}

function oneOf(list, value, what) {
  if (!list.includes(value)) throw new Error(`${what} must be ${list.join(', ')}, not ${JSON.stringify(value)}`);
  return value;
}

/** The curve t = τ(v) that starts as the iso-line `iso`: τ is that border of the surface's t_range. */
export function curveFromIsoLine(scene, surfaceName, iso) {
  const surface = surfacePatches(scene).find((p) => p.name === surfaceName);
  const range = Array.isArray(surface?.t_range) ? surface.t_range : [];
  const tau = asText(range[iso === 't1' ? 1 : 0]);
  return { t: tau === '' ? '0' : tau, replaces: iso === 't1' ? 't1' : 't0' };
}

/**
 * Write one field of a referenced end. key and value:
 *   surface: a name; at: 't0' | 't1' | { t, replaces }; tau: text (the curve's τ);
 *   replaces: 't0' | 't1'; continuity; power: a number or expression text;
 *   scale: 'gap' | 'surface'; flip: boolean (false leaves no field).
 */
export function setEndField(patch, end, key, value) {
  const e = referenced(patch, end);
  switch (key) {
    case 'surface':
      e.surface = String(value);
      break;
    case 'at':
      if (isObject(value)) e.at = { t: String(value.t), replaces: oneOf(ISO_LINES, value.replaces ?? 't0', 'replaces') };
      else e.at = oneOf(ISO_LINES, value, 'at');
      break;
    case 'tau':
      if (!isObject(e.at)) throw new Error(`end ${end} is met at an iso-line, not along a curve`);
      e.at.t = String(value);
      break;
    case 'replaces':
      if (!isObject(e.at)) throw new Error(`end ${end} is met at an iso-line, not along a curve`);
      e.at.replaces = oneOf(ISO_LINES, value, 'replaces');
      break;
    case 'continuity':
      e.continuity = oneOf(CONTINUITIES, value, 'continuity');
      break;
    case 'power':
      if (typeof value === 'number' && !Number.isFinite(value)) throw new Error('power must be a finite number or an expression');
      e.power = typeof value === 'number' ? value : String(value);
      break;
    case 'scale':
      e.scale = oneOf(SCALES, value, 'scale');
      break;
    case 'flip':
      if (value === true) e.flip = true;
      else delete e.flip;
      break;
    default:
      throw new Error(`unknown end field ${JSON.stringify(key)}`);
  }
}

/**
 * The current value of a power that is not a number: a numeric text, or a parameter's
 * name (its slider value). Anything else (an expression in v, a sum) is null.
 */
export function powerValue(scene, power) {
  if (typeof power === 'number') return Number.isFinite(power) ? power : null;
  if (typeof power !== 'string') return null;
  if (NUMBER.test(power)) return Number(power);
  const p = isObject(scene?.parameters) ? scene.parameters[power.trim()] : null;
  return isObject(p) && Number.isFinite(p.value) ? p.value : null;
}

/** The order the referenced ends need per coordinate (0 when none is by reference). */
export function neededOrder(patch) {
  let order = 0;
  for (const end of ENDS) {
    const e = readEnd(patch, end);
    if (e) order = Math.max(order, ORDER_FOR[e.continuity]);
  }
  return order;
}

/**
 * What "attach" gives a typed end: the first surface whose `meets` names this end (at its
 * `meets.at`), else the first surface the other end does not meet (a blend joins two), else
 * the first surface, at t0; tangency (position on a coordinate of order 2,
 * which tangency would exceed), power 1. orders: the resolved { x, y, z } orders, if known.
 */
export function attachDefaults(scene, patch, end, orders = {}) {
  checkEnd(end);
  const surfaces = surfacePatches(scene);
  const meeting = surfaces.find((p) => isObject(p.meets) && p.meets.patch === patch.name && p.meets.end === end);
  const other = endOf(patch, end === 'u0' ? 'u1' : 'u0')?.surface;
  const surface = meeting || surfaces.find((p) => p.name !== other) || surfaces[0];
  if (!surface) throw new Error('the scene has no "surface" patch to attach to');
  const lowest = Math.min(...AXES.map((axis) => (Number.isFinite(orders?.[axis]) ? orders[axis] : 4)));
  return {
    surface: surface.name,
    at: meeting && meeting.meets.at === 't1' ? 't1' : 't0',
    continuity: lowest < 4 ? 'position' : 'tangency',
    power: 1,
  };
}

/**
 * Give a typed end by reference: `ends.<end>` from `defaults` ({ surface, at, continuity,
 * power }); that end's typed boundary lists go (the solver refuses both); the scene
 * becomes version 3 if it was older.
 */
export function attach(scene, patch, end, defaults) {
  checkEnd(end);
  if (isByReference(patch, end)) throw new Error(`end ${end} of ${JSON.stringify(patch.name)} is already given by reference`);
  if (!isObject(patch.ends)) patch.ends = {};
  const { surface, at = 't0', continuity = 'tangency', power = 1 } = defaults;
  patch.ends[end] = { surface: String(surface), at, continuity, power };
  if (isObject(patch.boundary)) {
    for (const axis of AXES) {
      const comp = patch.boundary[axis];
      if (!isObject(comp)) continue;
      delete comp[end];
      if (Object.keys(comp).length === 0) delete patch.boundary[axis];
    }
    if (Object.keys(patch.boundary).length === 0) delete patch.boundary;
  }
  if (!(typeof scene.version === 'number' && scene.version >= 3)) scene.version = 3;
}

/**
 * `op` with an explicit order for every coordinate (a blend with no end by reference
 * needs them): a single form gets `order` when the resolved orders agree, else the
 * per-coordinate form; no operator becomes the solver's default of those orders.
 */
export function withExplicitOrders(op, orders) {
  for (const axis of AXES) {
    if (!ORDERS.includes(orders?.[axis])) throw new Error(`no resolved order for ${axis}`);
  }
  const same = AXES.every((axis) => orders[axis] === orders.x);
  if (isObject(op) && !isPerCoordinate(op)) {
    if ('order' in op) return op;
    if (same) return { order: orders.x, ...op };
  }
  if (!isObject(op) && same) return perCoordinate(undefined, orders).x;
  const out = perCoordinate(op, orders);
  for (const axis of AXES) {
    if (!isObject(out[axis])) out[axis] = perCoordinate(undefined, orders)[axis];
    else if (!('order' in out[axis])) out[axis] = { order: orders[axis], ...out[axis] };
  }
  return out;
}

/** The longest expression a scene may hold (cpp/common/limits.hpp kExpressionChars). */
export const EXPRESSION_CHARS = 1000;
const PRIMES = ['', 'ᵤ', 'ᵤᵤ', 'ᵤᵤᵤ'];

/**
 * Why `derived` (the solver's { x: [X, X_u, (X_uu)], y, z } for end `end`) cannot be typed
 * in: a text longer than an expression may be would make a scene that does not load. Null
 * when it can.
 */
export function detachRefusal(end, derived) {
  for (const axis of AXES) {
    const list = Array.isArray(derived?.[axis]) ? derived[axis] : [];
    // A NURBS surface's border is B-spline data the expression language shows but cannot type.
    if (list.some((t) => typeof t === 'string' && t.includes('bspline('))) {
      return 'cannot detach: this end meets a NURBS surface, whose border is B-spline data (shown as bspline(…)), '
        + 'not an expression one can type; the end stays by reference';
    }
    const k = list.findIndex((t) => typeof t === 'string' && t.length > EXPRESSION_CHARS);
    if (k >= 0) {
      return `cannot detach: the derived ${axis}${PRIMES[k] ?? `^(${k})`}(${end === 'u0' ? 0 : 1}) has ${list[k].length} characters, `
        + `more than an expression may have (${EXPRESSION_CHARS}); the end stays by reference`;
    }
  }
  return null;
}

/**
 * Turn a referenced end into typed expressions: `derived` is the solver's
 * { x: [X, X_u, (X_uu)], y, z } for it (texts with the parameters' current values), written
 * into boundary.<axis>.<end>; `ends.<end>` goes (and `ends` when empty). The operator gets
 * explicit orders from `orders` (the resolved { x, y, z }) when what the solver would infer
 * from the ends left by reference differs (none left, or a curvature end detached beside a
 * tangency one: the typed X_uu needs order 6 still). Refuses (throws, changing nothing) texts
 * longer than an expression may be (detachRefusal).
 */
export function detach(patch, end, derived, orders) {
  referenced(patch, end);
  for (const axis of AXES) {
    const list = derived?.[axis];
    if (!Array.isArray(list) || list.length === 0 || !list.every((t) => typeof t === 'string')) {
      throw new Error(`no derived conditions for ${axis} at ${end}`);
    }
  }
  const refusal = detachRefusal(end, derived);
  if (refusal) throw new Error(refusal);
  const left = ENDS.filter((e) => e !== end && isByReference(patch, e));
  const inferred = Math.max(0, ...left.map((e) => ORDER_FOR[readEnd(patch, e).continuity]));
  const explicit = left.length === 0 || AXES.some((axis) => orders?.[axis] !== inferred);
  const operator = explicit ? withExplicitOrders(patch.operator, orders) : patch.operator; // may throw: nothing changed yet
  if (!isObject(patch.boundary)) patch.boundary = {};
  for (const axis of AXES) {
    if (!isObject(patch.boundary[axis])) patch.boundary[axis] = {};
    patch.boundary[axis][end] = [...derived[axis]];
  }
  delete patch.ends[end];
  if (Object.keys(patch.ends).length === 0) delete patch.ends;
  if (explicit) patch.operator = operator;
}

/**
 * Which field of end `end` of patch number `index` a solver message is about: the key
 * after "patches[<index>].ends.<end>." ('at', 'power', 'surface', …; 'end' when the
 * message names the end itself), or null when it is about something else.
 */
export function endErrorField(message, index, end) {
  const prefix = `patches[${index}].ends.${end}`;
  const text = String(message);
  // The end a message is about is the first it names ("patches[2].ends.u0.at: meets t1 of
  // 'cyl', which patches[1].ends.u1 replaces by a curve" is about patches[2].ends.u0).
  const first = /patches\[\d+\]\.ends\.u[01]/.exec(text);
  if (!first || first[0] !== prefix) return null;
  const rest = text.slice(first.index + prefix.length);
  const m = /^\.([A-Za-z_]+)/.exec(rest);
  if (m) return m[1];
  return /^[:\s]/.test(rest) || rest === '' ? 'end' : null;
}
