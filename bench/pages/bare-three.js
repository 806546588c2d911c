// The cold-start floor (scripts/bench-page.mjs): three.js unbundled from node_modules, one
// MeshStandardMaterial sphere of 64×64 segments under the page's light rig, drawn once;
// window.__bareFirstFrameAt is set when that frame has been presented, exactly as the page's
// window.__pdesurf.firstFrameAt is (web/viewer/viewer.js).
import * as THREE from '/node_modules/three/build/three.module.js';

const renderer = new THREE.WebGLRenderer({ antialias: true });
renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
renderer.setClearColor(0x20242b, 1);
renderer.setSize(window.innerWidth, window.innerHeight, false);
document.body.appendChild(renderer.domElement);

const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera(40, window.innerWidth / window.innerHeight, 0.01, 1000);
camera.up.set(0, 0, 1);
camera.position.set(3, -4, 2.5);
camera.lookAt(0, 0, 0);
scene.add(new THREE.HemisphereLight(0xffffff, 0x505058, 2.0));
const key = new THREE.DirectionalLight(0xffffff, 2.2);
key.position.set(0.6, 1.2, 2);
camera.add(key);
scene.add(camera);
scene.add(new THREE.Mesh(new THREE.SphereGeometry(1, 64, 64), new THREE.MeshStandardMaterial({ color: 0x6fa8dc, roughness: 0.5 })));

// As the page draws (in an animation frame), and marked as it marks (the next frame's
// callback, which runs once the drawn frame has gone to the compositor).
requestAnimationFrame(() => {
  renderer.render(scene, camera);
  requestAnimationFrame(() => { window.__bareFirstFrameAt = performance.now(); });
});
