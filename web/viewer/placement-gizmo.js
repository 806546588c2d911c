// Moving, turning and scaling a surface in the 3D view with three's TransformControls.
// A placement { translate: [x, y, z], rotate: [rx, ry, rz] (degrees), scale: s } maps a
// point X of the surface as modelled to X' = T + R·(s·X), R = Rx·Ry·Rz: exactly an Object3D
// with position T, rotation Euler(rx, ry, rz, 'XYZ') and scale (s, s, s).
// The gizmo sits at a pivot (a world point, e.g. the middle of the drawn surface) and turns
// and scales about it; the placement it reports keeps that point where the gizmo puts it.
// While dragging, onDrag(placement) lets the page move the drawn mesh (previewMesh, no
// solve); at the release onCommit(placement) is the one step to keep. Orbiting pauses
// during a drag. Scaling is uniform: the factor of the axis dragged applies to all three.
import * as THREE from 'three';
import { lazyTransformControls } from './lazy-transform-controls.js';

export const MODES = ['translate', 'rotate', 'scale'];
export const IDENTITY = Object.freeze({ translate: [0, 0, 0], rotate: [0, 0, 0], scale: 1 });
const MIN_SCALE = 1e-3; // a drag through the pivot does not flip or collapse the surface

const DIGITS = 1e6;
/** Rounded to 1e-6 (numbers in links stay short); -0 becomes 0. */
export const round6 = (x) => Math.round(x * DIGITS) / DIGITS + 0;

/** A placement with defaults filled in and its numbers rounded; angles in (-180, 180]. */
export function normalizePlacement(p = {}) {
  const t = p.translate || IDENTITY.translate;
  const r = p.rotate || IDENTITY.rotate;
  const angle = (a) => {
    let d = round6(((a % 360) + 360) % 360);
    if (d > 180) d = round6(d - 360);
    return d;
  };
  return { translate: t.map(round6), rotate: r.map(angle), scale: round6(p.scale ?? 1) };
}

/** The placement as position, quaternion and uniform scale of `object`. */
export function applyPlacement(object, p) {
  const r = p.rotate || IDENTITY.rotate;
  object.position.fromArray(p.translate || IDENTITY.translate);
  object.rotation.set(...r.map(THREE.MathUtils.degToRad), 'XYZ');
  object.scale.setScalar(p.scale ?? 1);
  object.updateMatrix();
  return object;
}

/** The 4×4 matrix of X -> T + R·(s·X). */
export function placementMatrix(p) {
  return applyPlacement(new THREE.Object3D(), p).matrix.clone();
}

/** The placement an object carries (its scale taken as uniform from x). */
export function placementOf(object) {
  const e = new THREE.Euler().setFromQuaternion(object.quaternion, 'XYZ');
  return normalizePlacement({
    translate: object.position.toArray(),
    rotate: [e.x, e.y, e.z].map(THREE.MathUtils.radToDeg),
    scale: object.scale.x,
  });
}

/**
 * Show a mesh solved at placement `before` as if placed at `now`, without a solve: the mesh
 * object gets the relative transform A(now)·A(before)⁻¹. clearPreview undoes it (the
 * viewer does on every setPatches: a new solve carries its placement in its positions).
 */
export function previewMesh(mesh, before, now) {
  const m = placementMatrix(now).multiply(placementMatrix(before).invert());
  m.decompose(mesh.position, mesh.quaternion, mesh.scale);
  mesh.updateMatrix();
  mesh.updateMatrixWorld(true);
}

export function clearPreview(mesh) {
  mesh.position.set(0, 0, 0);
  mesh.quaternion.identity();
  mesh.scale.set(1, 1, 1);
  mesh.updateMatrix();
  mesh.updateMatrixWorld(true);
}

/** A world point to put the gizmo on: the middle of the mesh's bounds (with its preview). */
export function pivotOf(mesh) {
  const box = new THREE.Box3().setFromObject(mesh);
  return box.isEmpty() ? [0, 0, 0] : box.getCenter(new THREE.Vector3()).toArray();
}

/** scene, camera, dom (the canvas), orbit (OrbitControls, paused while dragging), render(). */
export function createPlacementGizmo({ scene, camera, dom, orbit, render }) {
  // The gizmo drives `handle`, which sits at the pivot with the placement's rotation and
  // scale; `local` is the pivot in the surface's own coordinates (what T + R·s·local maps
  // to the handle's position), so T = handle − R·s·local after any move.
  const handle = new THREE.Object3D();
  handle.name = 'placement handle';
  scene.add(handle);
  const local = new THREE.Vector3();

  const controls = lazyTransformControls({ scene, camera, dom, orbit, render, setUp: listen });

  let target = null; // { name, onDrag, onCommit }
  let start = null; // the placement when the drag began
  let current = null;

  function fromHandle() {
    const q = handle.quaternion;
    const s = handle.scale.x;
    const t = handle.position.clone().sub(local.clone().multiplyScalar(s).applyQuaternion(q));
    const e = new THREE.Euler().setFromQuaternion(q, 'XYZ');
    return normalizePlacement({ translate: t.toArray(), rotate: [e.x, e.y, e.z].map(THREE.MathUtils.radToDeg), scale: s });
  }

  function listen(gizmo) {
    gizmo.addEventListener('mouseDown', () => {
      start = current;
    });
    gizmo.addEventListener('objectChange', () => {
      if (!target) return;
      if (gizmo.mode === 'scale') {
        // Uniform: the first axis in the handle's name (X, Y, Z, XY…, XYZ) gives the factor.
        const axis = (gizmo.axis || 'X').match(/[XYZ]/)?.[0] || 'X';
        const s = Math.max(MIN_SCALE, Math.abs(handle.scale[axis.toLowerCase()]));
        handle.scale.setScalar(s);
        handle.updateMatrixWorld();
        render();
      }
      current = fromHandle();
      target.onDrag(current, target.name);
    });
    gizmo.addEventListener('mouseUp', () => {
      if (!target || !start) return;
      const was = start;
      start = null;
      if (JSON.stringify(current) !== JSON.stringify(was)) target.onCommit(current, target.name);
    });
  }

  return {
    /**
     * Put the gizmo on the surface `name` placed at `placement`, at the world point `pivot`
     * (default: its translate). onDrag(placement, name) during a drag, onCommit(placement,
     * name) at the release of a drag that changed it.
     */
    attach(name, placement, pivot = null, { onDrag = () => {}, onCommit = () => {} } = {}) {
      current = normalizePlacement(placement);
      applyPlacement(handle, current);
      const T = new THREE.Vector3().fromArray(current.translate);
      const P = pivot ? new THREE.Vector3().fromArray(pivot) : T.clone();
      // local = R⁻¹(P − T)/s
      local.copy(P).sub(T).applyQuaternion(handle.quaternion.clone().invert()).divideScalar(current.scale || 1);
      handle.position.copy(P);
      handle.updateMatrixWorld();
      target = { name, onDrag, onCommit };
      start = null;
      const gizmo = controls.get();
      gizmo.enabled = true;
      gizmo.attach(handle);
      render();
    },

    detach() {
      target = null;
      start = null;
      const gizmo = controls.peek();
      gizmo?.detach();
      if (gizmo) gizmo.enabled = false;
      orbit.enabled = true;
      render();
    },

    /** 'translate' | 'rotate' | 'scale'. */
    setMode(mode) {
      if (!MODES.includes(mode)) throw new Error(`unknown gizmo mode ${JSON.stringify(mode)}`);
      controls.get().setMode(mode);
      render();
    },

    mode: () => controls.peek()?.mode ?? 'translate',
    /** The surface the gizmo is on, or null. */
    attached: () => (target ? target.name : null),
    /** The placement the gizmo shows now. */
    placement: () => (current ? { ...current, translate: [...current.translate], rotate: [...current.rotate] } : null),
    /** Where the gizmo is (world) and its hovered handle ('X', 'XY', 'XYZE'…, or null). */
    pivot: () => handle.position.toArray(),
    axis: () => controls.peek()?.axis ?? null,
    dragging: () => controls.peek()?.dragging ?? false,
    /** Whether the pointer is on the gizmo or dragging it (other tools leave such presses alone). */
    busy: () => Boolean(target) && (controls.peek().dragging || controls.peek().axis !== null),

    previewMesh,
    clearPreview,
    pivotOf,
  };
}
