// Every place a patch names another patch, in one list: rename, the dependents a delete asks
// about and the outliner's upstream all walk this, so a new kind of reference is added once
// (issue 39: rename updated a blend's surface but not a chain's patch nor a fill's borders).
import { isObject } from './patch-names.js';

/**
 * The references of one patch: [{ holder, key, role, where }] with holder[key] the name of
 * the patch referred to. role: 'blend' (a pde end on a surface), 'chain' (a pde end continuing
 * a patch), 'fill' (a Bézier border on a surface), 'loop' (a fill's border), 'meets' (a
 * surface's own join, naming the blend that meets it: downstream, not a condition).
 * where: the end or edge ('u0', 'v1', …) or, for a loop border, its `at`.
 */
export function referencesOf(patch) {
  const out = [];
  if (!isObject(patch)) return out;
  if (patch.kind === 'pde' && isObject(patch.ends)) {
    for (const end of ['u0', 'u1']) {
      const e = patch.ends[end];
      if (!isObject(e)) continue;
      if (typeof e.surface === 'string') out.push({ holder: e, key: 'surface', role: 'blend', where: end });
      if (typeof e.patch === 'string') out.push({ holder: e, key: 'patch', role: 'chain', where: end });
    }
  }
  if (patch.kind === 'bezier' && isObject(patch.borders) && !Array.isArray(patch.borders)) {
    for (const [edge, b] of Object.entries(patch.borders))
      if (isObject(b) && typeof b.surface === 'string') out.push({ holder: b, key: 'surface', role: 'fill', where: edge });
  }
  if (patch.kind === 'fill' && Array.isArray(patch.borders)) {
    for (const b of patch.borders)
      if (isObject(b) && typeof b.patch === 'string')
        out.push({ holder: b, key: 'patch', role: 'loop', where: isObject(b.at) ? `curve replacing ${b.at.replaces ?? 't0'}` : String(b.at) });
  }
  if (isObject(patch.meets) && typeof patch.meets.patch === 'string') out.push({ holder: patch.meets, key: 'patch', role: 'meets', where: 'meets' });
  return out;
}

/** The names `patch`'s conditions come from (every reference but a surface's `meets`), each once, in order. */
export function conditionSources(patch) {
  const out = [];
  for (const r of referencesOf(patch)) if (r.role !== 'meets' && r.holder[r.key] && !out.includes(r.holder[r.key])) out.push(r.holder[r.key]);
  return out;
}
