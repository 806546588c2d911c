// Keeps the camera usable whatever the user does: zoom limited relative to the scene's
// size, near and far planes following the camera so nothing is clipped, a fit of every
// patch, double-click to centre a point of a surface, and orbit and zoom from the keyboard
// when the canvas has the focus. The scene's bounding sphere is computed lazily (at the
// start of a gesture, a fit, a key): a slider drag does not pay a pass over every vertex.
import * as THREE from 'three';
import { fitCameraToObject } from './fit-camera.js';

export const MIN_DISTANCE = 0.01; // orbit distance limits, × the scene's bounding radius
export const MAX_DISTANCE = 20;
const NEAR_FRACTION = 0.02; // what is closer than this × the orbit distance is clipped
const KEY_ORBIT = THREE.MathUtils.degToRad(7.5);
const KEY_ZOOM = 1.15;

/**
 * camera, controls (OrbitControls), surfaces (the group of patch meshes), dom (the canvas),
 * render(). Returns { invalidate(), fit(), afterMove(), clip(), state() }.
 */
export function createCameraRig({ camera, controls, surfaces, dom, render }) {
  let sphere = null; // bounding sphere of the patches, or null until asked for
  let dirty = true;

  function bounds() {
    if (dirty) {
      dirty = false;
      const box = new THREE.Box3().setFromObject(surfaces);
      sphere = box.isEmpty() ? null : box.getBoundingSphere(new THREE.Sphere());
      if (sphere) {
        sphere.radius = Math.max(sphere.radius, 1e-9);
        controls.minDistance = MIN_DISTANCE * sphere.radius;
        controls.maxDistance = MAX_DISTANCE * sphere.radius;
      }
    }
    return sphere;
  }

  // Near and far enclose the whole scene seen from where the camera is (within the limits).
  function clip() {
    const s = bounds();
    if (!s) return;
    const toCentre = camera.position.distanceTo(s.center);
    const orbit = Math.max(camera.position.distanceTo(controls.target), 1e-12);
    const far = (toCentre + s.radius) * 1.05;
    const near = Math.max(toCentre - s.radius * 1.05, orbit * NEAR_FRACTION, far * 1e-5);
    if (near !== camera.near || far !== camera.far) {
      camera.near = near;
      camera.far = far;
      camera.updateProjectionMatrix();
    }
  }

  controls.addEventListener('start', bounds); // before the gesture's first update clamps

  // A move the user asked for outside a drag (a key, a double-click, the fit button): the
  // controls' start and end events around it, so listeners (the share link) see a gesture.
  function asGesture(move) {
    controls.dispatchEvent({ type: 'start' });
    move();
    controls.dispatchEvent({ type: 'end' });
  }
  controls.addEventListener('change', () => {
    clip();
    render();
  });

  // Double-click on a surface: that point becomes the orbit centre and moves to the middle
  // of the view (the camera slides with it, so the view direction stays).
  const raycaster = new THREE.Raycaster();
  dom.addEventListener('dblclick', (ev) => {
    const rect = dom.getBoundingClientRect();
    const ndc = new THREE.Vector2(((ev.clientX - rect.left) / rect.width) * 2 - 1, 1 - ((ev.clientY - rect.top) / rect.height) * 2);
    raycaster.setFromCamera(ndc, camera);
    const hit = raycaster.intersectObjects(surfaces.children, false)[0];
    if (!hit) return;
    asGesture(() => {
      camera.position.add(hit.point.clone().sub(controls.target));
      controls.target.copy(hit.point);
      controls.update();
    });
  });

  // Arrow keys orbit, + and − zoom; only while the canvas has the focus, so they never
  // fight a slider or a text field.
  dom.tabIndex = 0;
  dom.setAttribute('aria-label', '3D view: arrow keys orbit, + and − zoom, F fits the view, double-click centres a point');
  dom.addEventListener('keydown', (ev) => {
    if (ev.ctrlKey || ev.metaKey || ev.altKey) return;
    const act = {
      ArrowLeft: () => controls.rotateLeft(KEY_ORBIT),
      ArrowRight: () => controls.rotateLeft(-KEY_ORBIT),
      ArrowUp: () => controls.rotateUp(KEY_ORBIT),
      ArrowDown: () => controls.rotateUp(-KEY_ORBIT),
      // OrbitControls' dollyOut brings the camera closer.
      '+': () => controls.dollyOut(KEY_ZOOM),
      '=': () => controls.dollyOut(KEY_ZOOM),
      '-': () => controls.dollyIn(KEY_ZOOM),
      _: () => controls.dollyIn(KEY_ZOOM),
    }[ev.key];
    if (!act) return;
    ev.preventDefault();
    asGesture(act);
  });

  return {
    /** The patches changed: bounds are recomputed when next needed. */
    invalidate() {
      dirty = true;
    },

    /** Frame every patch from the default direction; byUser: the fit button or F (a gesture). */
    fit(byUser = false) {
      dirty = true;
      const move = () => {
        bounds();
        fitCameraToObject(camera, controls, surfaces);
        clip();
        render();
      };
      if (byUser) asGesture(move);
      else move();
    },

    /** The camera was placed from outside (a link): limits and planes follow it. */
    afterMove() {
      bounds();
      controls.update();
      clip();
      render();
    },

    /** For the tests: { near, far, minDistance, maxDistance, radius, distance }. */
    state() {
      const s = bounds();
      return {
        near: camera.near, far: camera.far, minDistance: controls.minDistance, maxDistance: controls.maxDistance,
        radius: s ? s.radius : null, centre: s ? s.center.toArray() : null,
        distance: camera.position.distanceTo(controls.target),
      };
    },
  };
}
