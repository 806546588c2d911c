// Fitting a coordinate's boundary lists (boundary.<axis>.u0 / .u1) to its operator's
// order. The solver refuses more conditions than order/2, so lowering the order must
// drop the higher derivative conditions; they are kept here so that raising the order
// again brings them back instead of zeros. Entries are term arrays (version 1) or
// expression strings (version 2); the stash only moves them. An end given by reference
// (version 3, `ends.<end>`) has no typed list and gets none: the solver derives it.

const ENDS = ['u0', 'u1'];
const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);

export function createBoundaryStash() {
  // "patch\0axis\0end" -> Map(derivative index -> terms taken out of the scene)
  const store = new Map();
  const slot = (patchName, axis, end) => {
    const key = `${patchName}\0${axis}\0${end}`;
    if (!store.has(key)) store.set(key, new Map());
    return store.get(key);
  };

  return {
    /** Forget everything (another scene was opened). */
    clear() {
      store.clear();
    },

    /**
     * Make patch.boundary[axis].u0 and .u1 exactly `count` entries long: extra entries
     * move into the stash, missing ones come back from it or are `zero` ([] for a
     * version-1 term list, "0" for a version-2 expression).
     */
    fit(patch, axis, count, zero = []) {
      const typed = ENDS.filter((end) => !(isObject(patch.ends) && isObject(patch.ends[end])));
      if (typed.length === 0) return;
      if (!isObject(patch.boundary)) patch.boundary = {};
      if (!isObject(patch.boundary[axis])) patch.boundary[axis] = {};
      const comp = patch.boundary[axis];
      for (const end of typed) {
        const list = Array.isArray(comp[end]) ? comp[end] : [];
        const kept = slot(patch.name, axis, end);
        for (let i = count; i < list.length; i++) kept.set(i, list[i]);
        list.length = Math.min(list.length, count);
        for (let i = list.length; i < count; i++) {
          // Moved back, not copied: the scene and the stash never share an entry.
          list.push(kept.has(i) ? kept.get(i) : structuredClone(zero));
          kept.delete(i);
        }
        comp[end] = list;
      }
    },
  };
}
