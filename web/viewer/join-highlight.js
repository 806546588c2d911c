// Highlights of joins on the surface: a thick line (three's Line2, width in pixels)
// along the boundary row of a blend where it meets a surface. The patch's vertex (i, j)
// is at j*(nu+1)+i, so side u0 is the column i = 0, u1 the column i = nu, v0 the row
// j = 0 and v1 the row j = nv.
// Failing joins are red, the others ticked in the joins panel yellow.
import * as THREE from 'three';
import { Line2 } from 'three/addons/lines/Line2.js';
import { LineGeometry } from 'three/addons/lines/LineGeometry.js';
import { LineMaterial } from 'three/addons/lines/LineMaterial.js';

export const FAIL_COLOR = 0xff2d55;
export const PICK_COLOR = 0xffe14d;

/** The grid size of a solved patch from its uvs (vertex 1 is at u = 1/nu). */
export function gridOf(patch) {
  const V = patch.positions.length / 3;
  const nu = Math.round(1 / patch.uvs[2]);
  return { nu, nv: V / (nu + 1) - 1 };
}

/** Positions (flat, 3 per point) along one side: "u0", "u1", "v0" or "v1". */
export function boundaryLine(patch, side) {
  const { nu, nv } = gridOf(patch);
  const alongV = side === 'u0' || side === 'u1'; // a column: j runs
  const n = alongV ? nv : nu;
  const fixed = side === 'u1' ? nu : side === 'v1' ? nv : 0;
  const out = new Float32Array(3 * (n + 1));
  for (let t = 0; t <= n; t++) {
    const k = 3 * (alongV ? t * (nu + 1) + fixed : fixed * (nu + 1) + t);
    out.set(patch.positions.subarray(k, k + 3), 3 * t);
  }
  return out;
}

export function createJoinHighlight(overlays) {
  const group = new THREE.Group();
  group.name = 'join highlights';
  group.renderOrder = 10;
  overlays.add(group);
  const material = (color) => new LineMaterial({
    color, linewidth: 6, depthTest: false, transparent: true, // seen through the patches too
  });
  const materials = { fail: material(FAIL_COLOR), pick: material(PICK_COLOR) };
  const resolution = new THREE.Vector2(1, 1);

  return {
    /** items: [{ key, patch (solved patch), end ("u0" | "u1" | "v0" | "v1"), fail }] */
    show(items) {
      for (const l of [...group.children]) {
        group.remove(l);
        l.geometry.dispose();
      }
      for (const { key, patch, end, fail } of items) {
        if (!patch || patch.positions.length < 6) continue;
        const g = new LineGeometry();
        g.setPositions(boundaryLine(patch, end));
        const line = new Line2(g, fail ? materials.fail : materials.pick);
        line.computeLineDistances();
        line.renderOrder = 10;
        line.userData.joinKey = key;
        group.add(line);
      }
    },
    setResolution(w, h) {
      resolution.set(w, h);
      for (const m of Object.values(materials)) m.resolution.copy(resolution);
    },
    /** Keys of the drawn highlights (tests). */
    keys() {
      return group.children.map((l) => l.userData.joinKey);
    },
  };
}
