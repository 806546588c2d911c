// The border picker's screen-space hit test (web/viewer/border-picker.js) on made-up
// projections, the borders it takes from a solved grid, and the placement arithmetic of
// web/viewer/placement-gizmo.js (X' = T + R·(s·X), R = Rx·Ry·Rz).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as THREE from 'three';
import { nearestBorder, distanceToSegment, bordersOf, pickOf, screenProjector } from '../../web/viewer/border-picker.js';
import { gridTopology } from '../../web/viewer/grid-topology.js';
import {
  normalizePlacement, placementMatrix, placementOf, applyPlacement, previewMesh, clearPreview,
} from '../../web/viewer/placement-gizmo.js';

// Borders drawn in the plane z = 0 and "projected" by dropping z: screen = (x, y).
const flat = (x, y) => [x, y];
const border = (name, ...pts) => ({ patch: name, border: 't0', points: Float32Array.from(pts.flatMap(([x, y]) => [x, y, 0])) });

test('the nearest segment wins, whichever border and segment it is on', () => {
  const a = border('a', [0, 0], [100, 0], [100, 100]); // an L
  const b = border('b', [0, 50], [50, 50]);
  let hit = nearestBorder([a, b], flat, 95, 40, 10); // 5 from a's second segment, 45 from b
  assert.equal(hit.border, a);
  assert.equal(hit.segment, 1);
  assert.ok(Math.abs(hit.distance - 5) < 1e-9);
  assert.deepEqual(hit.at, [100, 40]);
  hit = nearestBorder([a, b], flat, 25, 47, 10);
  assert.equal(hit.border, b);
  assert.equal(hit.segment, 0);
  assert.ok(Math.abs(hit.s - 0.5) < 1e-9);
});

test('nothing farther than the radius is hit; the radius itself is', () => {
  const a = border('a', [0, 0], [100, 0]);
  assert.equal(nearestBorder([a], flat, 50, 10.001, 10), null);
  assert.equal(nearestBorder([a], flat, 50, 10, 10).border, a);
  assert.equal(nearestBorder([a], flat, 50, 23, 24).border, a, 'a touch radius reaches farther');
  // Past an end the distance is to the end point, not to the infinite line.
  assert.equal(nearestBorder([a], flat, 108, 7, 10), null); // hypot(8, 7) > 10
  assert.equal(nearestBorder([], flat, 0, 0, 10), null);
});

test('a tie goes to the border listed first', () => {
  const a = border('a', [0, -5], [100, -5]);
  const b = border('b', [0, 5], [100, 5]);
  assert.equal(nearestBorder([a, b], flat, 50, 0, 10).border, a);
  assert.equal(nearestBorder([b, a], flat, 50, 0, 10).border, b);
  // The same border twice along one segment shared by two of its own segments: the first.
  const c = border('c', [0, 0], [10, 0], [0, 0]);
  assert.equal(nearestBorder([c], flat, 5, 3, 10).segment, 0);
});

test('degenerate projected segments are points; a single-point border too', () => {
  // Seen end-on: every point of the border lands on one pixel.
  const endOn = border('e', [40, 40], [40, 40], [40, 40]);
  const hit = nearestBorder([endOn], flat, 43, 44, 10);
  assert.equal(hit.border, endOn);
  assert.ok(Math.abs(hit.distance - 5) < 1e-9);
  assert.equal(nearestBorder([endOn], flat, 60, 40, 10), null);
  assert.deepEqual(distanceToSegment(3, 4, 0, 0, 0, 0), { distance: 5, s: 0 });
  const single = border('s', [10, 10]);
  assert.equal(nearestBorder([single], flat, 12, 10, 10).border, single);
});

test('points behind the camera are ignored, with the segments touching them', () => {
  // z < 0 means "behind": this projector returns null there.
  const proj = (x, y, z) => (z < 0 ? null : [x, y]);
  const pts = Float32Array.of(0, 0, 1, 50, 0, -1, 100, 0, 1, 150, 0, 1);
  const b = { patch: 'p', border: 't1', points: pts };
  assert.equal(nearestBorder([b], proj, 25, 0, 10), null, 'segment 0 ends behind the camera');
  assert.equal(nearestBorder([b], proj, 75, 0, 10), null, 'segment 1 starts behind the camera');
  const hit = nearestBorder([b], proj, 125, 0, 10);
  assert.equal(hit.segment, 2);
  // A projection that yields NaN never wins.
  assert.equal(nearestBorder([b], () => [NaN, NaN], 0, 0, 10), null);
});

test('screenProjector: client pixels of the canvas, null behind a perspective camera', () => {
  const camera = new THREE.PerspectiveCamera(90, 2, 0.1, 100);
  camera.position.set(0, 0, 10);
  camera.lookAt(0, 0, 0);
  camera.updateProjectionMatrix();
  const dom = { getBoundingClientRect: () => ({ left: 100, top: 50, width: 800, height: 400 }) };
  const p = screenProjector(camera, dom);
  assert.deepEqual(p(0, 0, 0), [500, 250]); // the middle of the canvas
  const up = p(0, 10, 0); // 45° up: the top edge
  assert.ok(Math.abs(up[0] - 500) < 1e-6 && Math.abs(up[1] - 50) < 1e-6, String(up));
  assert.equal(p(0, 0, 20), null);
  assert.equal(p(0, 0, 10), null); // at the eye
});

test('bordersOf: t0 is the grid column i = 0, t1 the column i = nu, from v0 to v1; a pde patch offers u0, u1, a Bézier patch four, a fill none', () => {
  const nu = 4, nv = 3;
  const { uvs, indices } = gridTopology(nu, nv);
  // S(t, v) = (t, v, 0) sampled at t = i/nu, v = j/nv.
  const positions = new Float32Array(3 * (nu + 1) * (nv + 1));
  for (let j = 0; j <= nv; j++) for (let i = 0; i <= nu; i++) positions.set([i / nu, j / nv, 0], 3 * (j * (nu + 1) + i));
  const patch = { name: 'plane', kind: 'separable', positions, uvs, indices };
  const [t0, t1] = bordersOf(patch);
  assert.equal(t0.border, 't0');
  assert.equal(t1.border, 't1');
  assert.equal(t0.points.length, 3 * (nv + 1));
  for (let j = 0; j <= nv; j++) {
    assert.deepEqual([...t0.points.subarray(3 * j, 3 * j + 3)], [0, Math.fround(j / nv), 0]);
    assert.deepEqual([...t1.points.subarray(3 * j, 3 * j + 3)], [1, Math.fround(j / nv), 0]);
  }
  assert.deepEqual(pickOf(t1), { patch: 'plane', border: 't1', endpoints: [[1, 0, 0], [1, 1, 0]], extent: 1 });
  // A pde patch's ends are the same columns; a Bézier patch's v0 and v1 are the rows j = 0, nv.
  const pde = bordersOf({ ...patch, name: 'blend', kind: 'pde' });
  assert.deepEqual(pde.map((b) => b.border), ['u0', 'u1']);
  assert.deepEqual([...pde[1].points], [...t1.points]);
  const bezier = bordersOf({ ...patch, name: 'net', kind: 'bezier' });
  assert.deepEqual(bezier.map((b) => b.border), ['u0', 'u1', 'v0', 'v1']);
  assert.deepEqual(pickOf(bezier[3]), { patch: 'net', border: 'v1', endpoints: [[0, 1, 0], [1, 1, 0]], extent: 1 });
  assert.deepEqual(bordersOf({ ...patch, kind: 'fill' }), []);
});

const close = (a, b, eps = 1e-9) => a.every((x, k) => Math.abs(x - b[k]) <= eps);

test('placement: X\' = T + Rx·Ry·Rz·(s·X), and back from an object', () => {
  const p = { translate: [1, 2, 3], rotate: [90, 0, 90], scale: 2 };
  const X = new THREE.Vector3(1, 0, 0);
  // Rz(90)·x = y; Ry(0); Rx(90)·y = z: so (1,0,0) -> 2·(0,0,1) + T.
  const got = X.clone().applyMatrix4(placementMatrix(p)).toArray();
  assert.ok(close(got, [1, 2, 5]), String(got));
  const o = applyPlacement(new THREE.Object3D(), { translate: [0.5, -1, 0], rotate: [10, -20, 30], scale: 1.5 });
  assert.deepEqual(placementOf(o), { translate: [0.5, -1, 0], rotate: [10, -20, 30], scale: 1.5 });
});

test('normalizePlacement rounds to 1e-6, fills defaults and keeps angles in (-180, 180]', () => {
  assert.deepEqual(normalizePlacement({}), { translate: [0, 0, 0], rotate: [0, 0, 0], scale: 1 });
  const n = normalizePlacement({ translate: [0.1 + 0.2, -1e-9, 1 / 3], rotate: [270, -190, 180], scale: 1.00000049 });
  assert.deepEqual(n, { translate: [0.3, 0, 0.333333], rotate: [-90, 170, 180], scale: 1 });
  assert.ok(Object.is(n.translate[1], 0), '-0 stays out of links');
});

test('previewMesh moves positions solved at one placement to another; clearPreview undoes it', () => {
  const before = { translate: [1, 0, 0], rotate: [0, 0, 45], scale: 1 };
  const now = { translate: [0, 2, 1], rotate: [30, 0, 10], scale: 0.5 };
  const X = new THREE.Vector3(0.3, -0.7, 1.1);
  const drawn = X.clone().applyMatrix4(placementMatrix(before)); // as the solve drew it
  const mesh = new THREE.Mesh();
  previewMesh(mesh, before, now);
  const shown = drawn.clone().applyMatrix4(mesh.matrixWorld).toArray();
  assert.ok(close(shown, X.clone().applyMatrix4(placementMatrix(now)).toArray(), 1e-6), String(shown));
  clearPreview(mesh);
  assert.ok(mesh.matrixWorld.equals(new THREE.Matrix4()));
});
