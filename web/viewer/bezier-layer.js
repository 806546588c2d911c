// The bezier overlays of the drawn scene: rebuilt after every solve, while what the
// user chose to see (per patch: solved net, initial net, normals) outlives the rebuilds.
import { bezierOverlays, disposeOverlay } from './bezier-overlays.js';

export const OVERLAY_KEYS = ['solvedNet', 'initialNet', 'normals'];

export function createBezierLayer(group) {
  const shown = new Map(); // patch name -> Set of keys the user turned on
  const built = new Map(); // patch name -> { solvedNet, initialNet, normals }
  let editing = null; // the patch whose initial net is being edited: its net is shown regardless

  function apply(name) {
    const o = built.get(name);
    if (!o) return;
    const on = shown.get(name) || new Set();
    for (const key of OVERLAY_KEYS) o[key].visible = on.has(key) || (key === 'initialNet' && editing === name);
  }

  return {
    /** Replace the overlays with those of freshly solved patches. */
    update(patches) {
      for (const o of built.values()) {
        for (const key of OVERLAY_KEYS) {
          group.remove(o[key]);
          disposeOverlay(o[key]);
        }
      }
      built.clear();
      for (const p of patches) {
        if (p.kind !== 'bezier' || !p.netSize) continue;
        const o = bezierOverlays(p);
        for (const key of OVERLAY_KEYS) group.add(o[key]);
        built.set(p.name, o);
        apply(p.name);
      }
    },

    setVisible(name, key, on) {
      if (!OVERLAY_KEYS.includes(key)) throw new Error(`unknown overlay ${JSON.stringify(key)}`);
      if (!shown.has(name)) shown.set(name, new Set());
      shown.get(name)[on ? 'add' : 'delete'](key);
      apply(name);
    },

    /** The patch whose initial net is being edited (or null). */
    setEditing(name) {
      const before = editing;
      editing = name;
      apply(before);
      apply(name);
    },

    /** A new scene: nothing shown. */
    reset() {
      shown.clear();
      editing = null;
    },

    /** The initial net's group (userData.points, rows, cols) of one patch, or null. */
    initialNet(name) {
      return built.get(name)?.initialNet || null;
    },

    /** What is visible now, for the tests: nets, net points and arrows. */
    counts() {
      const c = { solvedNets: 0, initialNets: 0, netPoints: 0, arrows: 0 };
      for (const o of built.values()) {
        if (o.solvedNet.visible) { c.solvedNets++; c.netPoints += o.solvedNet.userData.pointCount; }
        if (o.initialNet.visible) { c.initialNets++; c.netPoints += o.initialNet.userData.pointCount; }
        if (o.normals.visible) c.arrows += o.normals.userData.arrowCount;
      }
      return c;
    },
  };
}
