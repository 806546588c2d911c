// Deleting a patch, and what to do with the blends and fills that name it (its dependents):
// delete them too, or detach them (their ends/borders become typed data from the last solve).
import { isObject, patchesOf, requirePatch } from './patch-names.js';
import { detach } from './ends-edit.js';
import { AXES } from './operator-edit.js';
import { referencesOf } from './patch-references.js';

const EDGES = ['v0', 'u1', 'v1', 'u0'];

/**
 * The patches that name surface `name`: [{ patch, kind: 'blend', ends: ['u0', …] }] for
 * blends whose ends are given by reference to it, [{ patch, kind: 'fill', edges: ['v0', …] }]
 * for Bézier fills whose borders lie on it; version 4: [{ patch, kind: 'chain', ends }] for
 * pde patches whose ends continue it and [{ patch, kind: 'loop', edges: ['u1', …] }] for
 * fills whose loop runs over it. In scene order.
 */
export function dependentsOf(scene, name) {
  const out = [];
  for (const p of patchesOf(scene)) {
    if (!isObject(p) || p.name === name) continue;
    const refs = referencesOf(p).filter((r) => r.role !== 'meets' && r.holder[r.key] === name);
    for (const [role, field] of [['blend', 'ends'], ['fill', 'edges'], ['chain', 'ends'], ['loop', 'edges']]) {
      let where = refs.filter((r) => r.role === role).map((r) => r.where);
      if (role === 'fill') where = EDGES.filter((e) => where.includes(e));
      if (where.length) out.push({ patch: p.name, kind: role, [field]: where });
    }
  }
  return out;
}

/** Every patch that depends on `name`, directly or through others (chains, loops), in scene order. */
export function downstreamOf(scene, name) {
  const seen = new Set([name]);
  const queue = [name];
  while (queue.length) {
    for (const d of dependentsOf(scene, queue.shift())) {
      if (seen.has(d.patch)) continue;
      seen.add(d.patch);
      queue.push(d.patch);
    }
  }
  return patchesOf(scene).filter((p) => isObject(p) && p.name !== name && seen.has(p.name)).map((p) => p.name);
}

const solvedPatch = (solved, name) => (Array.isArray(solved) ? solved.find((p) => p && p.name === name) : solved?.[name]);

/** The blend `patch` with `ends` detached, as a new object (the scene is not touched). */
function detachedBlend(patch, ends, solved) {
  const s = solvedPatch(solved, patch.name);
  const orders = Object.fromEntries(AXES.map((axis) => [axis, s?.operator?.[axis]?.order]));
  const copy = structuredClone(patch);
  for (const end of ends) {
    const derived = s?.ends?.[end]?.derived;
    if (!derived) throw new Error(`${patch.name}.ends.${end}: no derived conditions from a good solve to detach with (solve the scene first)`);
    try {
      detach(copy, end, derived, orders);
    } catch (err) {
      throw new Error(`${patch.name}.ends.${end}: ${err.message}`);
    }
  }
  return copy;
}

/**
 * The fill `patch` with `edges` detached: their border ring(s) (one for membrane, two for
 * thin-plate: the fixed ones) are typed into control_net from the solved net. A fill
 * with no control_net (all four borders by reference) gets the whole solved net.
 */
function detachedFill(patch, edges, solved) {
  const s = solvedPatch(solved, patch.name);
  const [n, m] = Array.isArray(patch.degree) ? patch.degree : [];
  const net = s?.controlNet;
  if (!net || !Array.isArray(s.netSize) || s.netSize[0] !== n + 1 || s.netSize[1] !== m + 1 || net.length !== 3 * (n + 1) * (m + 1)) {
    throw new Error(`${patch.name}.borders: no solved control net of degree ${JSON.stringify(patch.degree)} to detach with (solve the scene first)`);
  }
  // The solved net in doubles: the detached rings are exactly what was solved, so the borders
  // still by reference meet them at the corners as before.
  const point = (i, j) => [0, 1, 2].map((c) => net[3 * (i * (m + 1) + j) + c]);
  const copy = structuredClone(patch);
  if (!Array.isArray(copy.control_net)) {
    copy.control_net = [];
    for (let i = 0; i <= n; i++) for (let j = 0; j <= m; j++) copy.control_net.push(point(i, j));
  } else {
    if (copy.control_net.length !== (n + 1) * (m + 1)) throw new Error(`${patch.name}.control_net: expected ${(n + 1) * (m + 1)} points for degree ${JSON.stringify(patch.degree)}`);
    const rings = patch.energy === 'membrane' ? 1 : 2;
    const onEdge = { v0: (i, j) => j < rings, v1: (i, j) => j > m - rings, u0: (i) => i < rings, u1: (i) => i > n - rings };
    for (let i = 0; i <= n; i++) {
      for (let j = 0; j <= m; j++) if (edges.some((e) => onEdge[e](i, j))) copy.control_net[i * (m + 1) + j] = point(i, j);
    }
  }
  for (const e of edges) delete copy.borders[e];
  if (Object.keys(copy.borders).length === 0) delete copy.borders;
  return copy;
}

/**
 * Delete patch `name`. When blends or fills name it (dependentsOf), options.dependents says
 * what happens to them: 'delete' removes them too; 'detach' types their ends (the last good
 * solve's derived conditions, web/state/ends-edit.js detach) and borders (the solved control
 * net) in place, so they keep their shape but no longer follow. options.solved: the last
 * good solve's result patches (solver.solve(...).patches, or { name: patch }), needed for
 * 'detach'. Without a choice, throws asking it. Surfaces whose `meets` names a deleted patch
 * lose that `meets`. Returns the names of the patches deleted.
 */
export function deletePatch(scene, name, options = {}) {
  requirePatch(scene, name);
  const deps = dependentsOf(scene, name);
  const choice = options.dependents;
  if (deps.length > 0 && choice !== 'delete' && choice !== 'detach') {
    const list = deps.map((d) => `${JSON.stringify(d.patch)} (${(d.ends || d.edges).join(', ')})`).join(', ');
    throw new Error(`${JSON.stringify(name)} is named by ${list}: delete ${deps.length === 1 ? 'it' : 'them'} too, or detach ${deps.length === 1 ? 'it' : 'them'} (keep the shape as typed data)?`);
  }
  const gone = new Set([name]);
  const replaced = new Map();
  for (const d of deps) {
    const patch = requirePatch(scene, d.patch);
    if (choice === 'delete') {
      // A chain or a fill over what goes is gone too, and so is whatever depends on it.
      gone.add(d.patch);
      for (const n of downstreamOf(scene, d.patch)) gone.add(n);
    } else if (d.kind === 'chain' || d.kind === 'loop') {
      throw new Error(`${JSON.stringify(d.patch)} continues ${JSON.stringify(name)} (${d.kind === 'chain' ? 'a chained end' : "a fill's loop"}): it cannot be detached; delete it too`);
    } else replaced.set(patch, d.kind === 'blend' ? detachedBlend(patch, d.ends, options.solved) : detachedFill(patch, d.edges, options.solved));
  }
  // Everything checked: now change the scene.
  scene.patches = scene.patches.filter((p) => !gone.has(p?.name)).map((p) => replaced.get(p) ?? p);
  for (const p of scene.patches) if (isObject(p?.meets) && gone.has(p.meets.patch)) delete p.meets;
  return [...gone];
}
