// Patch and parameter names for the scene-building edits: what the core accepts
// (scene_json.cpp: a patch name is 1-64 bytes of one-line text, unique; a parameter name
// is an identifier of at most 32 bytes that is not pi, e, u, v or t) and fresh unique ones.
import { PARAMETER_NAME, RESERVED, FUNCTIONS } from './expr-text.js';

export const MAX_PATCH_NAME = 64; // bytes of UTF-8, as the core counts them
// C0, DEL, C1, U+2028/2029: what cpp/common/text.cpp controlCharacterAt refuses.
const CONTROL = /[\u0000-\u001f\u007f-\u009f\u2028\u2029]/;

export const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
export const patchesOf = (scene) => (Array.isArray(scene?.patches) ? scene.patches : []);
export const findPatch = (scene, name) => patchesOf(scene).find((p) => isObject(p) && p.name === name);

/** The patch named `name`; throws naming it when there is none. */
export function requirePatch(scene, name, kind) {
  const p = findPatch(scene, name);
  if (!p) throw new Error(`there is no patch named ${JSON.stringify(String(name))}`);
  if (kind && p.kind !== kind) throw new Error(`patch ${JSON.stringify(name)} is a ${p.kind} patch, not a ${kind} patch`);
  return p;
}

/** Why `name` cannot name a patch (ignoring duplicates), or null. */
export function patchNameProblem(name) {
  if (typeof name !== 'string' || name === '') return 'a patch name cannot be empty';
  if (new TextEncoder().encode(name).length > MAX_PATCH_NAME) return `a patch name has at most ${MAX_PATCH_NAME} bytes (${JSON.stringify(name)} is longer)`;
  if (CONTROL.test(name)) return `a patch name is one line of text without control characters (${JSON.stringify(name)})`;
  if (!name.isWellFormed()) return `a patch name must be well-formed text (${JSON.stringify(name)} has a lone surrogate)`;
  return null;
}

/** Throw unless `name` is a valid patch name not used by another patch. */
export function checkNewPatchName(scene, name) {
  const problem = patchNameProblem(name);
  if (problem) throw new Error(problem);
  if (findPatch(scene, name)) throw new Error(`there is already a patch named ${JSON.stringify(name)}`);
}

/** `${base}1`, `${base}2`, …: the first not yet a patch name. */
export function uniquePatchName(scene, base) {
  for (let k = 1; ; k++) {
    const name = `${base}${k}`;
    if (!findPatch(scene, name)) return name;
  }
}

/** Whether `name` can be a new parameter of `scene`. */
export function isFreeParameterName(scene, name, taken = new Set()) {
  return PARAMETER_NAME.test(name) && !RESERVED.has(name) && !FUNCTIONS.has(name) && name !== '__proto__'
    && !taken.has(name) && !(isObject(scene?.parameters) && Object.hasOwn(scene.parameters, name));
}

/**
 * An identifier prefix made from a patch name: other characters become '_', a leading
 * digit gets a '_' before it, and it is cut so that `${prefix}_${key}` fits 32 bytes.
 */
export function parameterPrefix(patchName, fallback = 'p') {
  let p = String(patchName).replace(/[^A-Za-z0-9_]+/g, '_').replace(/^_+|_+$/g, '');
  if (p === '') p = fallback;
  if (/^[0-9]/.test(p)) p = `_${p}`;
  return p.slice(0, 20);
}

/**
 * A fresh parameter name for `key` of a patch: `${prefix}_${key}`, else with 2, 3, … after
 * it, never a name in `taken` (names chosen earlier in the same edit).
 */
export function uniqueParameterName(scene, prefix, key, taken = new Set()) {
  for (let k = 1; ; k++) {
    const name = `${prefix}_${key}${k === 1 ? '' : k}`;
    if (isFreeParameterName(scene, name, taken)) return name;
  }
}
