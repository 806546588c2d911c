// Building a scene from nothing: a new scene, renaming, duplicating and deleting patches,
// and the parameters no patch uses. Pure edits of the scene object (the page state, plain
// JSON, exactly what the solver reads); each validates first and throws an Error naming the
// field, so a refused edit leaves the scene as it was.
// Also here (split for size): surface-library.js (addSurface), scene-join.js (addBlend,
// addFill, addLoopFill), patch-delete.js (dependentsOf, deletePatch), placement.js (setPlacement),
// trig-curve.js (trigCurveFromSamples).
import { isObject, patchesOf, requirePatch, checkNewPatchName, findPatch, parameterPrefix, uniqueParameterName } from './patch-names.js';
import { namesIn, replaceNames } from './expr-text.js';
import { referencesOf } from './patch-references.js';

export { dependentsOf, deletePatch } from './patch-delete.js';
export { setPlacement, placePoint } from './placement.js';
export { addBlend, addFill, addLoopFill } from './scene-join.js';
export { trigCurveFromSamples } from './trig-curve.js';
export { addSurface, SURFACE_LIBRARY } from './surface-library.js';

/** A new, empty scene (the core refuses empty `patches`: the page does not solve it). */
export function newScene() {
  return { format: 'pdesurf-scene', version: 4, title: 'untitled', parameters: {}, patches: [] };
}

// Keys whose strings are names or choices, never expressions.
const NOT_EXPRESSIONS = new Set(['name', 'kind', 'method', 'energy', 'surface', 'patch', 'end', 'continuity', 'scale', 'replaces']);

/**
 * Every expression text in a patch, as { holder, key } places (holder[key] is the text):
 * every string under the patch except names and choices (and an `at` that is 't0'/'t1').
 */
export function expressionPlaces(patch) {
  const out = [];
  const walk = (node) => {
    if (Array.isArray(node)) {
      node.forEach((x, k) => (typeof x === 'string' ? out.push({ holder: node, key: k }) : walk(x)));
    } else if (isObject(node)) {
      for (const [key, x] of Object.entries(node)) {
        if (typeof x === 'string') {
          if (!NOT_EXPRESSIONS.has(key) && key !== 'at') out.push({ holder: node, key });
        } else walk(x);
      }
    }
  };
  walk(patch);
  return out;
}

/** The names (parameters, or anything else) the expressions of `patch` use. */
export function namesUsedBy(patch) {
  const used = new Set();
  for (const { holder, key } of expressionPlaces(patch)) for (const n of namesIn(holder[key])) used.add(n);
  return used;
}

/** The scene's parameters that no expression of any patch uses (token-wise), in scene order. */
export function unusedParameters(scene) {
  const used = new Set();
  for (const p of patchesOf(scene)) for (const n of namesUsedBy(p)) used.add(n);
  return Object.keys(isObject(scene?.parameters) ? scene.parameters : {}).filter((n) => !used.has(n));
}

/** Remove a parameter that no expression uses; refuses (naming the users) one that is used. */
export function removeParameter(scene, name) {
  if (!isObject(scene.parameters) || !Object.hasOwn(scene.parameters, name)) throw new Error(`parameters: there is no parameter ${JSON.stringify(String(name))}`);
  const users = patchesOf(scene).filter((p) => namesUsedBy(p).has(name)).map((p) => JSON.stringify(p.name));
  if (users.length > 0) throw new Error(`parameters.${name}: still used by ${users.join(', ')}; edit those expressions first`);
  delete scene.parameters[name];
}

/**
 * Rename a patch and every reference to it: blends' ends.*.surface, surfaces' meets.patch,
 * fills' borders.*.surface. Refuses an empty, too long or multi-line name, or a duplicate.
 */
export function renamePatch(scene, oldName, newName) {
  const patch = requirePatch(scene, oldName);
  if (newName === oldName) return;
  checkNewPatchName(scene, newName);
  patch.name = newName;
  // Every reference to it: blend ends, chained ends, Bézier borders, fill borders, meets.
  for (const p of patchesOf(scene)) for (const r of referencesOf(p)) if (r.holder[r.key] === oldName) r.holder[r.key] = newName;
}

/** `${base}${k}` for the first free k, base being `name` without trailing digits (cut to fit 64 bytes). */
function copyName(scene, name) {
  let base = name.replace(/[0-9]+$/, '');
  if (base === '') base = `${name}_`;
  while (new TextEncoder().encode(base).length > 58) base = [...base].slice(0, -1).join('');
  for (let k = 2; ; k++) if (!findPatch(scene, `${base}${k}`)) return `${base}${k}`;
}

/**
 * Duplicate a patch; returns the copy's name (`cylinder1` → `cylinder2`). The copy gets its
 * own copies of the parameters only this patch uses (the ones addSurface made for it), so
 * its sliders are its own; parameters other patches use too stay shared. With
 * { share: true } every parameter is shared (the copy follows the original's sliders).
 * A surface's `meets` is not copied (it names the original's blend end). A patch that meets
 * another's edge (by its ends, borders or loop) is refused: its copy would meet it too.
 */
export function duplicatePatch(scene, name, options = {}) {
  const patch = requirePatch(scene, name);
  const copy = structuredClone(patch);
  copy.name = copyName(scene, name);
  delete copy.meets;
  // A copy would meet every edge its original meets (a blend's or a chain's ends, a Bézier
  // border, a fill's loop): three sheets along each, which the core refuses. Said here, by name.
  const edge = referencesOf(copy).find((r) => r.role !== 'meets');
  if (edge) {
    throw new Error(`${JSON.stringify(name)} meets ${JSON.stringify(edge.holder[edge.key])} (its ${edge.role === 'loop' ? `border on ${edge.where}` : edge.where}): a copy would meet the same edge and three sheets would meet along it; detach it first to duplicate it`);
  }
  const own = {};
  if (!options.share && isObject(scene.parameters)) {
    const elsewhere = new Set();
    for (const p of patchesOf(scene)) if (p !== patch) for (const n of namesUsedBy(p)) elsewhere.add(n);
    const oldPrefix = `${parameterPrefix(name)}_`;
    const newPrefix = parameterPrefix(copy.name);
    const taken = new Set();
    for (const n of namesUsedBy(patch)) {
      if (!Object.hasOwn(scene.parameters, n) || elsewhere.has(n)) continue;
      const key = n.startsWith(oldPrefix) ? n.slice(oldPrefix.length) : n;
      own[n] = uniqueParameterName(scene, newPrefix, key, taken);
      taken.add(own[n]);
    }
    for (const { holder, key } of expressionPlaces(copy)) holder[key] = replaceNames(holder[key], own);
  }
  for (const [from, to] of Object.entries(own)) scene.parameters[to] = structuredClone(scene.parameters[from]);
  scene.patches.splice(scene.patches.indexOf(patch) + 1, 0, copy);
  return copy.name;
}

/**
 * The lowest scene version that can hold this scene: 4 with a placement or fill borders,
 * 3 with ends by reference, else the scene's own (so a scene that uses no version-4 field
 * can be handed to a core that reads version 3 only).
 */
export function lowestVersion(scene) {
  if (patchesOf(scene).some((p) => isObject(p) && (p.placement !== undefined || p.borders !== undefined))) return 4;
  return Math.min(scene.version, 3);
}
