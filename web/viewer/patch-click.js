// A click (or a tap) on a drawn patch names it; on the background, null. A press that
// travels (an orbit) or that another tool takes (the gizmo, the border picker, the
// control-point editor: `busy`) is no click. The page selects with it (web/features/build.js).
import * as THREE from 'three';

const CLICK_SLOP = 5; // CSS pixels a click may travel

/** { camera, dom, surfaces (the group of patch meshes), busy() } -> { onClick(fn(name | null)) } */
export function createPatchClick({ camera, dom, surfaces, busy }) {
  const raycaster = new THREE.Raycaster();
  let press = null;
  let listener = null;

  dom.addEventListener('pointerdown', (e) => {
    press = e.isPrimary && e.button === 0 && !busy() ? { id: e.pointerId, x: e.clientX, y: e.clientY } : null;
  });
  dom.addEventListener('pointercancel', () => {
    press = null;
  });
  dom.addEventListener('pointerup', (e) => {
    const p = press;
    press = null;
    if (!listener || !p || p.id !== e.pointerId || busy()) return;
    if (Math.hypot(e.clientX - p.x, e.clientY - p.y) > CLICK_SLOP) return;
    const rect = dom.getBoundingClientRect();
    const ndc = new THREE.Vector2(((e.clientX - rect.left) / rect.width) * 2 - 1, 1 - ((e.clientY - rect.top) / rect.height) * 2);
    raycaster.setFromCamera(ndc, camera);
    const visible = surfaces.children.filter((m) => m.isMesh && m.visible);
    const hit = raycaster.intersectObjects(visible, false)[0];
    listener(hit ? hit.object.name : null);
  });

  return {
    onClick(fn) {
      listener = fn;
    },
  };
}
