// three.js objects drawn over a bezier patch: a control net (grid lines + points) and
// the guiding normals (arrows in one LineSegments). Built from the solver's arrays.
import * as THREE from 'three';
import { arrowLength, arrowSegments, gridIndices, SEGMENTS_PER_ARROW } from './arrow-geometry.js';

// Colours chosen apart from the surfaces (orange blends, blue primaries) and the background.
export const SOLVED_NET_COLOR = 0xf4efd2;
export const INITIAL_NET_COLOR = 0xd77cff;
export const NORMAL_COLOR = 0x5fe08a;
const POINT_SIZE = 6; // pixels: nets stay readable however far the camera is

/** A net as a Group of LineSegments (the grid) and Points; userData.points is the Points. */
export function netObject(net, rows, cols, color, kind) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(net, 3)); // WebGL takes no doubles
  geometry.setIndex(gridIndices(rows, cols));
  geometry.computeBoundingSphere();
  const lines = new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color }));
  const points = new THREE.Points(geometry, new THREE.PointsMaterial({ color, size: POINT_SIZE, sizeAttenuation: false }));
  const group = new THREE.Group();
  group.add(lines, points);
  group.name = kind;
  group.userData = { kind, rows, cols, points, pointCount: rows * cols };
  return group;
}

/** The guiding normals as arrows on the solved surface. */
export function normalArrows(origins, vectors) {
  const segments = arrowSegments(origins, vectors, arrowLength(origins));
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(segments, 3));
  geometry.computeBoundingSphere();
  const lines = new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color: NORMAL_COLOR }));
  lines.name = 'normals';
  lines.userData = { kind: 'normals', arrowCount: segments.length / (6 * SEGMENTS_PER_ARROW) };
  return lines;
}

/** All overlays of one solved bezier patch: { solvedNet, initialNet, normals }, hidden. */
export function bezierOverlays(patch) {
  const [rows, cols] = patch.netSize;
  const out = {
    solvedNet: netObject(patch.controlNet, rows, cols, SOLVED_NET_COLOR, 'solvedNet'),
    initialNet: netObject(patch.initialNet, rows, cols, INITIAL_NET_COLOR, 'initialNet'),
    normals: normalArrows(patch.normalOrigins, patch.normalVectors),
  };
  for (const o of Object.values(out)) o.visible = false;
  return out;
}

/** Free an overlay's GPU buffers and materials. */
export function disposeOverlay(object) {
  object.traverse((o) => {
    o.geometry?.dispose();
    o.material?.dispose();
  });
}
