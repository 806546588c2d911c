// The scene object in memory is the page state: controls write into it, and
// JSON.stringify(scene) is exactly what the solver sees.
import { withParam, withOrder, orderOf, defaultParams } from './operator-edit.js';
import { createBoundaryStash } from './boundary-stash.js';
import { hasExpressions, setBoundarySlot, setForce, setSurfaceCoordinate } from './expression-edit.js';
import { addParameter, removeParameter } from './parameter-edit.js';
import { setRegionWeights } from './region-weights.js';
import { setControlPointCoordinate } from './control-net-edit.js';

const BEZIER_NUMBERS = ['lambda', 'gamma'];
export const DEFAULT_GRID = Object.freeze({ nu: 64, nv: 64 }); // what an example opens with

export function createSceneState() {
  const stash = createBoundaryStash(); // derivative conditions dropped by order changes

  const state = {
    scene: null,
    exampleId: null,
    grid: { ...DEFAULT_GRID },

    /** Replace the whole scene (example change). */
    setScene(scene, exampleId) {
      state.scene = scene;
      state.exampleId = exampleId;
      stash.clear();
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
      patch.operator = withParam(patch.operator, axis, name, value);
    },

    /**
     * Give one coordinate an operator of another order (default coefficients) and fit
     * its boundary lists to order/2 conditions. Returns the coordinate's new
     * coefficients; the same order again changes nothing (and returns null).
     */
    setOperatorOrder(patchName, axis, order) {
      const patch = state.pdePatch(patchName);
      if (orderOf(patch.operator, axis) === order) return null;
      patch.operator = withOrder(patch.operator, axis, order);
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
     * | { kind: 'surface', axis }.
     */
    setExpression(patchName, field, text) {
      const patch = state.patch(patchName);
      if (field.kind === 'boundary') setBoundarySlot(patch, field.axis, field.end, field.k, text);
      else if (field.kind === 'force') setForce(patch, field.axis, text);
      else if (field.kind === 'surface') setSurfaceCoordinate(patch, field.axis, text);
      else throw new Error(`unknown expression field ${JSON.stringify(field.kind)}`);
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
