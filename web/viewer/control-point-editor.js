// Picking and dragging a control point of the initial net in the 3D view. While a
// patch is being edited: a click near one of its initial net's points picks it (a
// raycaster on the net's Points), the picked point carries a marker and three's
// TransformControls, and dragging the gizmo reports the new position on every move.
// OrbitControls pauses while the gizmo is dragged, so the camera stays put.
import * as THREE from 'three';
import { lazyTransformControls } from './lazy-transform-controls.js';

const PICK_PIXELS = 10; // how near a click must be to a point
const CLICK_SLOP = 4; // pixels a press may travel and still count as a click, not an orbit
const MARKER_COLOR = 0xffe14d;

/**
 * scene, camera, dom (the canvas), orbit (OrbitControls), layer (bezier-layer.js),
 * render(); pointOf(patch, i, j) -> [x, y, z] as the scene has it (exact, not float32);
 * onPick(patch, i, j); onMove(patch, i, j, [x, y, z]).
 */
export function createControlPointEditor({ scene, camera, dom, orbit, layer, render, pointOf, onPick, onMove }) {
  const handle = new THREE.Object3D(); // what the gizmo moves
  scene.add(handle);
  const markerGeometry = new THREE.BufferGeometry();
  markerGeometry.setAttribute('position', new THREE.Float32BufferAttribute([0, 0, 0], 3));
  // Drawn over everything: the picked point must stay findable behind the surface.
  const marker = new THREE.Points(markerGeometry,
    new THREE.PointsMaterial({ color: MARKER_COLOR, size: 12, sizeAttenuation: false, depthTest: false }));
  marker.renderOrder = 10;
  marker.visible = false;
  handle.add(marker);

  let active = null; // { patch, i, j }
  const controls = lazyTransformControls({
    scene, camera, dom, orbit, render,
    setUp(gizmo) {
      gizmo.setSize(0.75);
      gizmo.addEventListener('objectChange', () => {
        if (active) onMove(active.patch, active.i, active.j, handle.position.toArray());
      });
    },
  });

  // Put the marker and the gizmo on the active point (not mid-drag: the gizmo owns it then).
  function place() {
    if (!active || !layer.initialNet(active.patch)) {
      marker.visible = false;
      const idle = controls.peek();
      idle?.detach();
      if (idle) idle.enabled = false; // no pointer capture or hover work while nothing is edited
      return;
    }
    const gizmo = controls.get();
    if (!gizmo.dragging) handle.position.fromArray(pointOf(active.patch, active.i, active.j));
    marker.visible = true;
    gizmo.enabled = true;
    if (gizmo.object !== handle) gizmo.attach(handle);
  }

  const raycaster = new THREE.Raycaster();
  const pointer = new THREE.Vector2();
  function pick(clientX, clientY) {
    const net = layer.initialNet(active.patch);
    if (!net) return;
    const rect = dom.getBoundingClientRect();
    pointer.set(((clientX - rect.left) / rect.width) * 2 - 1, -((clientY - rect.top) / rect.height) * 2 + 1);
    raycaster.setFromCamera(pointer, camera);
    // The Points threshold is in world units: PICK_PIXELS at the distance of what the camera orbits.
    const dist = camera.position.distanceTo(orbit.target);
    const worldPerPixel = (2 * dist * Math.tan(THREE.MathUtils.degToRad(camera.fov) / 2)) / rect.height;
    raycaster.params.Points.threshold = PICK_PIXELS * worldPerPixel;
    const hits = raycaster.intersectObject(net.userData.points, false);
    if (hits.length === 0) return;
    const best = hits.reduce((a, b) => (b.distanceToRay < a.distanceToRay ? b : a));
    const { cols } = net.userData;
    onPick(active.patch, Math.floor(best.index / cols), best.index % cols);
  }

  let press = null;
  dom.addEventListener('pointerdown', (e) => {
    // A press on the gizmo (its hover axis is set) drags it; it is not a pick.
    press = active && e.button === 0 && (controls.peek()?.axis ?? null) === null ? { x: e.clientX, y: e.clientY } : null;
  });
  dom.addEventListener('pointerup', (e) => {
    if (press && active && Math.hypot(e.clientX - press.x, e.clientY - press.y) <= CLICK_SLOP) pick(e.clientX, e.clientY);
    press = null;
  });

  return {
    /** Edit point (i, j) of `patch` (null: stop editing). */
    setActive(patch, i = 0, j = 0) {
      active = patch === null ? null : { patch, i, j };
      place();
      render();
    },

    /** After a solve rebuilt the nets: follow the point. */
    refresh() {
      place();
    },

    /** The point being edited, or null. */
    active() {
      return active ? { ...active } : null;
    },

    /** Whether the gizmo is being dragged now. */
    dragging() {
      return controls.peek()?.dragging ?? false;
    },
  };
}
