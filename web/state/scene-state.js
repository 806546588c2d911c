// The scene object in memory is the page state: controls write into it, and
// JSON.stringify(scene) is exactly what the solver sees.
import { withParam, withOrder, orderOf, defaultParams, defaultOperator, isPerCoordinate, AXES } from './operator-edit.js';
import { createBoundaryStash } from './boundary-stash.js';
import { hasExpressions, setBoundarySlot, setForce, setSurfaceCoordinate, setSurfaceRangeEnd } from './expression-edit.js';
import { addParameter, removeParameter, setParameterValue } from './parameter-edit.js';
import { setRegionWeights } from './region-weights.js';
import { setControlPointCoordinate } from './control-net-edit.js';
import { setEndField, attach, attachDefaults, detach, neededOrder } from './ends-edit.js';

const BEZIER_NUMBERS = ['lambda', 'gamma'];
export const DEFAULT_GRID = Object.freeze({ nu: 64, nv: 64 }); // what an example opens with

export function createSceneState() {
  const stash = createBoundaryStash(); // derivative conditions dropped by order changes
  // The last good solve's order per pde patch and coordinate ({ x, y, z }): a version-3
  // operator may leave its order to the solver, and edits of it need them.
  let solvedOrders = new Map();
  const ordersOf = (name) => solvedOrders.get(name) || {};

  const state = {
    scene: null,
    exampleId: null,
    grid: { ...DEFAULT_GRID },

    /** Replace the whole scene (example change). */
    setScene(scene, exampleId) {
      state.scene = scene;
      state.exampleId = exampleId;
      stash.clear();
      solvedOrders = new Map();
    },

    /** After a good solve: note each blend's resolved orders (result patches' operator). */
    noteSolved(patches) {
      solvedOrders = new Map();
      for (const p of patches) {
        if (p && p.operator) solvedOrders.set(p.name, Object.fromEntries(AXES.map((axis) => [axis, p.operator[axis].order])));
      }
    },

    /** The resolved { x, y, z } orders of a blend at the last good solve ({} before one). */
    solvedOrders(patchName) {
      return { ...ordersOf(patchName) };
    },

    /** The pde patches of the scene, in scene order. */
    pdePatches() {
      return (state.scene?.patches || []).filter((p) => p && p.kind === 'pde');
    },

    /** The pde patch named `name`; throws if there is none. */
    pdePatch(name) {
      const patch = state.pdePatches().find((p) => p.name === name);
      if (!patch) throw new Error(`no pde patch named ${JSON.stringify(name)}`);
      return patch;
    },

    /**
     * Set one coefficient (b, s, a, coefficients[k], ...) of one coordinate. The operator
     * becomes per coordinate; the other coordinates keep their scene values.
     */
    setOperatorParam(patchName, axis, name, value) {
      const patch = state.pdePatch(patchName);
      patch.operator = withParam(patch.operator, axis, name, value, ordersOf(patchName));
    },

    /**
     * Give one coordinate an operator of another order (default coefficients) and fit
     * its boundary lists to order/2 conditions. Returns the coordinate's new
     * coefficients; the same order again changes nothing (and returns null).
     */
    setOperatorOrder(patchName, axis, order) {
      const patch = state.pdePatch(patchName);
      if (orderOf(patch.operator, axis) === order) return null;
      patch.operator = withOrder(patch.operator, axis, order, ordersOf(patchName));
      stash.fit(patch, axis, order / 2, hasExpressions(state.scene) ? '0' : []);
      return defaultParams(order);
    },

    /** Choose the solution method; "auto" is the default and leaves no field behind. */
    setMethod(patchName, method) {
      const patch = state.pdePatch(patchName);
      if (method === 'auto') delete patch.method;
      else patch.method = String(method);
    },

    /** The method the scene asks for ("auto" when it names none). */
    methodOf(patchName) {
      const patch = state.pdePatches().find((p) => p.name === patchName);
      return patch && typeof patch.method === 'string' ? patch.method : 'auto';
    },

    /** The patch named `name` of any kind; throws if there is none. */
    patch(name) {
      const patch = (state.scene?.patches || []).find((p) => p && p.name === name);
      if (!patch) throw new Error(`no patch named ${JSON.stringify(name)}`);
      return patch;
    },

    /** Index of a patch in scene.patches (the solver names fields by it), or -1. */
    patchIndex(name) {
      return (state.scene?.patches || []).findIndex((p) => p && p.name === name);
    },

    /**
     * Write one expression field: { kind: 'boundary', axis, end, k } | { kind: 'force', axis }
     * | { kind: 'surface', axis } | { kind: 'range', key: 't_range' | 'v_range', k: 0 | 1 }.
     */
    setExpression(patchName, field, text) {
      const patch = state.patch(patchName);
      if (field.kind === 'boundary') setBoundarySlot(patch, field.axis, field.end, field.k, text);
      else if (field.kind === 'force') setForce(patch, field.axis, text);
      else if (field.kind === 'surface') setSurfaceCoordinate(patch, field.axis, text);
      else if (field.kind === 'range') setSurfaceRangeEnd(patch, field.key, field.k, text);
      else throw new Error(`unknown expression field ${JSON.stringify(field.kind)}`);
    },

    /**
     * Write one field of a blend's end given by reference (web/state/ends-edit.js
     * setEndField). A continuity above what a coordinate's order carries raises that
     * order (default coefficients); returns the coordinates raised (often none).
     */
    setEndField(patchName, end, key, value) {
      const patch = state.pdePatch(patchName);
      setEndField(patch, end, key, value);
      return key === 'continuity' ? state.fitOrdersToEnds(patchName) : [];
    },

    /**
     * Raise the coordinates whose resolved order is below what the referenced ends ask
     * (never lower one: a higher order is allowed). Returns the axes raised.
     */
    fitOrdersToEnds(patchName) {
      const patch = state.pdePatch(patchName);
      const needed = neededOrder(patch);
      const orders = ordersOf(patchName);
      const low = AXES.filter((axis) => Number.isFinite(orders[axis]) && orders[axis] < needed);
      if (low.length === 0) return [];
      const single = !patch.operator || (typeof patch.operator === 'object' && !isPerCoordinate(patch.operator));
      if (low.length === AXES.length && single) {
        // All three rise together: the single form stays single.
        patch.operator = defaultOperator(needed);
        for (const axis of AXES) stash.fit(patch, axis, needed / 2, '0');
      } else {
        for (const axis of low) state.setOperatorOrder(patchName, axis, needed);
      }
      for (const axis of low) orders[axis] = needed;
      return low;
    },

    /** Give a typed end by reference with the defaults of ends-edit.js attachDefaults. */
    attachEnd(patchName, end) {
      const patch = state.pdePatch(patchName);
      attach(state.scene, patch, end, attachDefaults(state.scene, patch, end, ordersOf(patchName)));
    },

    /** Type a referenced end's derived conditions (the last solve's texts) in its place. */
    detachEnd(patchName, end, derived) {
      detach(state.pdePatch(patchName), end, derived, ordersOf(patchName));
    },

    /** The bezier patch named `name`; throws if there is none. */
    bezierPatch(name) {
      const patch = state.patch(name);
      if (patch.kind !== 'bezier') throw new Error(`patch ${JSON.stringify(name)} is not a bezier patch`);
      return patch;
    },

    /** Set a bezier patch's λ or γ to a number (the page offers this only when the scene has a number). */
    setBezierNumber(name, key, value) {
      if (!BEZIER_NUMBERS.includes(key)) throw new Error(`expected lambda or gamma, not ${JSON.stringify(key)}`);
      if (!Number.isFinite(value)) throw new Error(`${key} must be a finite number`);
      state.bezierPatch(name)[key] = value;
    },

    /** Nine region weights (web/state/region-weights.js) into normals.lambda_weights. */
    setRegionWeights(name, regions) {
      setRegionWeights(state.bezierPatch(name), regions);
    },

    /** One coordinate of the initial net's point (i, j). */
    setControlPointCoordinate(name, i, j, axis, value) {
      setControlPointCoordinate(state.bezierPatch(name), i, j, axis, value);
    },

    addParameter(name, value) {
      return addParameter(state.scene, name, value);
    },

    /** The page's grid (cells per direction, 1 .. 2048 each: the core's bound). */
    setGrid({ nu, nv }) {
      for (const [key, n] of [['nu', nu], ['nv', nv]])
        if (!Number.isInteger(n) || n < 1 || n > 2048) throw new Error(`the grid's ${key} must be a whole number from 1 to 2048, not ${n}`);
      Object.assign(state.grid, { nu, nv });
    },

    setParameter(name, value) {
      setParameterValue(state.scene, name, value);
    },

    removeParameter(name) {
      removeParameter(state.scene, name);
    },

    /** The text handed to the solver. */
    text() {
      return JSON.stringify(state.scene);
    },
  };
  return state;
}
