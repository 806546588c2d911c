// Turning one solved patch (typed arrays from the solver) into a three.js mesh.
import * as THREE from 'three';
import { kindInfo } from '../state/patch-kinds.js';

// Solved patches (kind "pde" blends and "bezier" variational surfaces) in one colour,
// the primary surfaces they join in another.
export const BLEND_COLOR = 0xe8913a;
export const PRIMARY_COLOR = 0x7fa3c8;

function makeMaterial(color) {
  // DoubleSide: open patches are seen from both sides while orbiting.
  return new THREE.MeshStandardMaterial({
    color,
    roughness: 0.55,
    metalness: 0.05,
    side: THREE.DoubleSide,
    // The wireframe overlay (viewer/shading.js) draws over the faces without z-fighting.
    polygonOffset: true,
    polygonOffsetFactor: 1,
    polygonOffsetUnits: 1,
  });
}

const materials = {
  blend: makeMaterial(BLEND_COLOR),
  primary: makeMaterial(PRIMARY_COLOR),
};

/**
 * A stand-in mesh per patch material, for compiling their shaders while the first solve
 * runs (compiling is the costliest part of the first frame). Same attributes as a patch.
 */
export function shaderWarmUpMeshes() {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(9), 3));
  g.setAttribute('normal', new THREE.BufferAttribute(Float32Array.of(0, 0, 1, 0, 0, 1, 0, 0, 1), 3));
  g.setAttribute('uv', new THREE.BufferAttribute(new Float32Array(6), 2));
  return Object.values(materials).map((m) => new THREE.Mesh(g, m));
}

/** BufferGeometry from { positions, normals, uvs, indices }. */
export function geometryFromPatch(patch) {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(patch.positions, 3));
  g.setAttribute('normal', new THREE.BufferAttribute(patch.normals, 3));
  g.setAttribute('uv', new THREE.BufferAttribute(patch.uvs, 2));
  g.setIndex(new THREE.BufferAttribute(patch.indices, 1));
  return g; // bounds computed lazily (see updateMeshFromPatch)
}

/**
 * A newer solve of the same patch on the same grid: its positions and normals replace the
 * attributes' arrays in place (the GPU buffers are updated, not recreated; uvs and indices
 * stay).
 */
export function updateMeshFromPatch(mesh, patch) {
  const g = mesh.geometry;
  for (const [name, array] of [['position', patch.positions], ['normal', patch.normals]]) {
    const a = g.getAttribute(name);
    a.array = array;
    a.needsUpdate = true;
  }
  // Bounds only when something asks (framing, picking): patch meshes are not frustum-culled,
  // so a slider drag does not pay two passes over every vertex per solve.
  g.boundingBox = null;
  g.boundingSphere = null;
  setCurvature(mesh, patch);
}

/** Whether `mesh` can take `patch` in place: same patch, same number of vertices. */
export function fitsMesh(mesh, patch) {
  return mesh.name === patch.name && mesh.userData.kind === patch.kind && mesh.geometry.getAttribute('position').array.length === patch.positions.length;
}

function setCurvature(mesh, patch) {
  // Per-vertex H and K from the module (solveSceneWith {curvature: true}), for the colour maps.
  if (patch.meanCurvature) {
    mesh.userData.curvature = { meanCurvature: patch.meanCurvature, gaussCurvature: patch.gaussCurvature };
  } else {
    delete mesh.userData.curvature;
  }
}

/** A mesh for one patch; userData keeps the name and kind for lookups and tests. */
export function meshFromPatch(patch) {
  const solved = kindInfo(patch.kind).solved;
  const mesh = new THREE.Mesh(geometryFromPatch(patch), solved ? materials.blend : materials.primary);
  mesh.name = patch.name;
  mesh.frustumCulled = false; // the view frames the patches; culling would compute bounds per solve
  mesh.userData = { kind: patch.kind, patchName: patch.name };
  setCurvature(mesh, patch);
  return mesh;
}
