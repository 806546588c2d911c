// Edits of a pde patch's `operator` field (docs/scene-format.md). Every edit returns
// the per-coordinate form { x: OP, y: OP, z: OP }; the coordinates not edited are split
// out of the single form exactly as the solver reads it (a 3-array gives one entry per
// coordinate, a scalar serves all three), so their expressions stay expressions.

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

/** A deep copy of `op` in the per-coordinate form; `op` itself is not changed. */
export function perCoordinate(op) {
  if (!isObject(op)) return {};
  if (!('order' in op)) return structuredClone(op); // already per coordinate
  const out = {};
  AXES.forEach((axis, i) => {
    const pick = (v) => structuredClone(Array.isArray(v) ? v[i] : v);
    const one = {};
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

/** `op` with one coefficient of one coordinate set; `name` is b, s, a, ... or coefficients[k]. */
export function withParam(op, axis, name, value) {
  checkAxis(axis);
  const out = perCoordinate(op);
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

/** `op` with one coordinate replaced by the default operator of `order`. */
export function withOrder(op, axis, order) {
  checkAxis(axis);
  const out = perCoordinate(op);
  out[axis] = defaultOperator(order);
  return out;
}
