// What the modeller marks on the drawn patches, by name, so it outlives the meshes being
// rebuilt by a solve: hidden patches, and the selected one (a light tint over its faces,
// whatever the shading mode: a second mesh on the same geometry, a child of the patch's
// mesh so it follows a placement preview and hides with it). Every solve's meshes come
// without a preview transform (placement-gizmo.js, previewMesh).
import * as THREE from 'three';
import { clearPreview } from './placement-gizmo.js';

export const SELECT_COLOR = 0xfff0b8;

export function createPatchMarks(surfaces) {
  const hidden = new Set();
  let selected = null;
  const tint = new THREE.Mesh(undefined, new THREE.MeshBasicMaterial({
    color: SELECT_COLOR, transparent: true, opacity: 0.38, depthWrite: false, side: THREE.DoubleSide,
  }));
  tint.name = 'selection tint';
  tint.frustumCulled = false;
  tint.renderOrder = 1;

  const meshOf = (name) => surfaces.children.find((m) => m.isMesh && m.name === name) || null;

  function apply() {
    for (const m of surfaces.children) m.visible = !hidden.has(m.name);
    const m = selected === null ? null : meshOf(selected);
    if (tint.parent && tint.parent !== m) tint.parent.remove(tint);
    if (m) {
      tint.geometry = m.geometry; // shared: in-place updates show at once
      if (tint.parent !== m) m.add(tint);
    }
  }

  return {
    meshOf,
    /** After setPatches: no preview transform, and the marks again on the (new) meshes. */
    solved() {
      for (const m of surfaces.children) clearPreview(m);
      apply();
    },
    setVisible(name, on) {
      if (on) hidden.delete(name);
      else hidden.add(name);
      apply();
    },
    select(name) {
      selected = name ?? null;
      apply();
    },
    /** For the tests: { selected, hidden: [names] }. */
    state() {
      return { selected, tinted: tint.parent ? tint.parent.name : null, hidden: [...hidden] };
    },
  };
}
