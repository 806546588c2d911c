// Frame an object: look at its bounding-sphere centre from a fixed oblique direction,
// far enough that the whole sphere fits the vertical and horizontal field of view.
import * as THREE from 'three';

const VIEW_DIR = new THREE.Vector3(1.0, -1.35, 0.85).normalize(); // z is up

export function fitCameraToObject(camera, controls, object, margin = 1.0) {
  const box = new THREE.Box3().setFromObject(object);
  if (box.isEmpty()) return;
  const sphere = box.getBoundingSphere(new THREE.Sphere());
  const radius = Math.max(sphere.radius, 1e-6);
  const vFov = THREE.MathUtils.degToRad(camera.fov);
  const hFov = 2 * Math.atan(Math.tan(vFov / 2) * camera.aspect);
  const dist = (margin * radius) / Math.sin(Math.min(vFov, hFov) / 2);
  camera.position.copy(sphere.center).addScaledVector(VIEW_DIR, dist);
  camera.near = dist / 100;
  camera.far = dist * 100;
  camera.updateProjectionMatrix();
  controls.target.copy(sphere.center);
  controls.update();
}
