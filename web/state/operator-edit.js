// Edits of a pde patch's `operator` field (docs/scene-format.md). Every edit returns
// the per-coordinate form { x: OP, y: OP, z: OP }; the coordinates not edited are split
// out of the single form exactly as the solver reads it (a 3-array gives one entry per
// coordinate, a scalar serves all three), so their expressions stay expressions.
// A version-3 blend with an end by reference may leave out `order` (the solver infers
// it from the ends' continuity); the per-coordinate form needs one per coordinate, so
// the edits take the solver's resolved orders ({ x, y, z } numbers) to fill it in.

export const AXES = ['x', 'y', 'z'];
export const ORDERS = [2, 4, 6];

// What a coordinate gets when its order changes: the papers' standard operators
// (order 4 with b = d = 1, c = 2 is seed 000's Fig. 2a).
const DEFAULTS = { 2: { s: 1, t: 1 }, 4: { b: 1, c: 2, d: 1 }, 6: { a: 1 } };

const COEFFICIENT = /^coefficients\[(\d+)\]$/;

/** A fresh operator of the given order with the default coefficients. */
export function defaultOperator(order) {
  if (!ORDERS.includes(order)) throw new Error(`operator order must be 2, 4 or 6, not ${JSON.stringify(order)}`);
  return { order, ...DEFAULTS[order] };
}

/** The coefficients of a default operator as the solver names them. */
export function defaultParams(order) {
  const { order: _, ...params } = defaultOperator(order);
  return params;
}

const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);

/** Whether `op` is already { x, y, z } (an empty object counts as one). */
export function isPerCoordinate(op) {
  return isObject(op) && !('order' in op) && Object.keys(op).every((key) => AXES.includes(key));
}

/**
 * A deep copy of `op` in the per-coordinate form; `op` itself is not changed. A single
 * form without `order` (or no operator at all) takes each coordinate's order from
 * `orders` (the resolved ones).
 */
export function perCoordinate(op, orders = {}) {
  if (!isObject(op)) {
    // No operator (version 3): the solver's defaults of the resolved orders, which are ours.
    const known = AXES.every((axis) => ORDERS.includes(orders?.[axis]));
    return known ? Object.fromEntries(AXES.map((axis) => [axis, defaultOperator(orders[axis])])) : {};
  }
  if (isPerCoordinate(op)) return structuredClone(op);
  const out = {};
  AXES.forEach((axis, i) => {
    const pick = (v) => structuredClone(Array.isArray(v) ? v[i] : v);
    const one = {};
    if (!('order' in op) && Number.isFinite(orders?.[axis])) one.order = orders[axis];
    for (const [key, v] of Object.entries(op)) {
      if (key === 'order') one.order = v;
      else if (key === 'coefficients' && Array.isArray(v)) one.coefficients = v.map(pick);
      else one[key] = pick(v);
    }
    out[axis] = one;
  });
  return out;
}

function checkAxis(axis) {
  if (!AXES.includes(axis)) throw new Error(`axis must be x, y or z, not ${JSON.stringify(axis)}`);
}

/**
 * `op` with one coefficient of one coordinate set; `name` is b, s, a, ... or coefficients[k].
 * orders: the resolved orders, for a single form without `order`.
 */
export function withParam(op, axis, name, value, orders = {}) {
  checkAxis(axis);
  const out = perCoordinate(op, orders);
  const one = isObject(out[axis]) ? out[axis] : (out[axis] = {});
  const m = COEFFICIENT.exec(name);
  if (m) {
    one.coefficients = Array.isArray(one.coefficients) ? one.coefficients : [];
    one.coefficients[Number(m[1])] = value;
  } else {
    one[name] = value;
  }
  return out;
}

/** The order the scene gives one coordinate, or undefined. */
export function orderOf(op, axis) {
  const one = perCoordinate(op)[axis];
  return isObject(one) ? one.order : undefined;
}

/** `op` with one coordinate replaced by the default operator of `order` (orders as for withParam). */
export function withOrder(op, axis, order, orders = {}) {
  checkAxis(axis);
  const out = perCoordinate(op, orders);
  out[axis] = defaultOperator(order);
  return out;
}
