// Picking a border in the 3D view: hovering draws the border under the pointer, a click (or
// a tap) picks it. Every patch is drawn on a grid whose vertex (i, j) is at j*(nu+1)+i with i
// along t or u and j along v (web/viewer/grid-topology.js): a surface's border t0 is the
// column i = 0 and t1 the column i = nu, each running from v0 (j = 0) to v1 (j = nv); a pde
// patch's ends u0 and u1 are the same columns; a Bézier patch also offers its rows v0, v1.
// A fill offers none (its border belongs to the patches it closes).
// The hit test is in screen space (the distance in CSS pixels from the pointer to the
// projected polylines), so a thin border far away is as easy to hit as a near one, and it
// needs no raycast against the meshes. Hovering only draws: it never changes the scene.
import * as THREE from 'three';
import { Line2 } from 'three/addons/lines/Line2.js';
import { LineGeometry } from 'three/addons/lines/LineGeometry.js';
import { LineMaterial } from 'three/addons/lines/LineMaterial.js';
import { boundaryLine } from './join-highlight.js';
import { kindInfo, isSurfaceKind } from '../state/patch-kinds.js';

export const HOVER_COLOR = 0x3fd8ff;
export const CHOSEN_COLOR = 0xa4ff5c;
export const MOUSE_RADIUS = 10; // CSS pixels from a border that still hit it
export const TOUCH_RADIUS = 24;
export const CLICK_SLOP = 5; // a press that travels farther is an orbit, not a pick
const HOVER_WIDTH = 4;
const CHOSEN_WIDTH = 3;


// A border's name -> its grid line (boundaryLine's side).
const GRID_SIDE = { t0: 'u0', t1: 'u1', u0: 'u0', u1: 'u1', v0: 'v0', v1: 'v1' };

/** The borders of one solved patch: [{ patch, border, points (flat xyz, along its grid line) }]. */
export function bordersOf(patch) {
  if (!patch.uvs || patch.positions.length < 6) return [];
  return kindInfo(patch.kind).borders.map((border) => ({ patch: patch.name, border, points: boundaryLine(patch, GRID_SIDE[border]) }));
}

/** Distance from (px, py) to the segment a-b and where along it (0..1) the nearest point is. */
export function distanceToSegment(px, py, ax, ay, bx, by) {
  const dx = bx - ax, dy = by - ay;
  const len2 = dx * dx + dy * dy;
  // A segment seen end-on (or of zero length) projects to a point.
  let s = len2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / len2 : 0;
  s = Math.min(1, Math.max(0, s));
  return { distance: Math.hypot(px - (ax + s * dx), py - (ay + s * dy)), s };
}

/**
 * The border nearest to the screen point (x, y) within `radius`, or null.
 * borders: [{ points: flat [x, y, z, ...], ... }]; projectFn(x, y, z) -> [sx, sy] in the same
 * units as (x, y), or null for a point behind the camera (a segment touching one is
 * ignored). Returns { border (the entry), segment (index of its first point), s, distance,
 * at: [sx, sy] }; on a tie the border listed first wins.
 */
export function nearestBorder(borders, projectFn, x, y, radius) {
  let best = null;
  for (const b of borders) {
    const pts = b.points;
    const n = Math.floor(pts.length / 3);
    let prev = n > 0 ? projectFn(pts[0], pts[1], pts[2]) : null;
    if (n === 1 && prev) consider(b, 0, prev, prev);
    for (let k = 1; k < n; k++) {
      const cur = projectFn(pts[3 * k], pts[3 * k + 1], pts[3 * k + 2]);
      if (prev && cur) consider(b, k - 1, prev, cur);
      prev = cur;
    }
  }
  return best;

  function consider(border, segment, a, b) {
    const { distance, s } = distanceToSegment(x, y, a[0], a[1], b[0], b[1]);
    if (!(distance <= radius)) return; // NaN from a bad projection never wins
    if (best && distance >= best.distance) return;
    best = { border, segment, s, distance, at: [a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])] };
  }
}

/**
 * The pick the callbacks receive: { patch, border, endpoints: [[x, y, z] at its start, at its
 * end], extent: the diagonal of its points' bounding box (a closed border's ends meet: its size
 * is not theirs) }.
 */
export function pickOf(entry) {
  const p = entry.points;
  const n = p.length;
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (let k = 0; k < n; k++) {
    lo[k % 3] = Math.min(lo[k % 3], p[k]);
    hi[k % 3] = Math.max(hi[k % 3], p[k]);
  }
  const extent = Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  return { patch: entry.patch, border: entry.border, endpoints: [[p[0], p[1], p[2]], [p[n - 3], p[n - 2], p[n - 1]]], extent };
}

/** projectFn for nearestBorder: world point -> client pixels of `dom`, null behind the camera. */
export function screenProjector(camera, dom) {
  camera.updateMatrixWorld();
  const m = new THREE.Matrix4().multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse);
  const rect = dom.getBoundingClientRect();
  const v = new THREE.Vector4();
  return (x, y, z) => {
    v.set(x, y, z, 1).applyMatrix4(m);
    if (!(v.w > 0)) return null; // clip w is the depth in front of the camera
    return [rect.left + ((v.x / v.w + 1) / 2) * rect.width, rect.top + ((1 - v.y / v.w) / 2) * rect.height];
  };
}

/**
 * scene (unused, kept for symmetry with the other tools), camera, dom (the canvas),
 * render(), overlays (the group the lines go into); busy() -> true while another tool owns
 * the pointer (the placement gizmo), so its presses are not picks.
 */
export function createBorderPicker({ camera, dom, render, overlays, busy = () => false }) {
  const group = new THREE.Group();
  group.name = 'border picker';
  overlays.add(group);
  const material = (color, linewidth) => new LineMaterial({ color, linewidth, depthTest: false, transparent: true });
  const hoverMaterial = material(HOVER_COLOR, HOVER_WIDTH);
  const chosenMaterial = material(CHOSEN_COLOR, CHOSEN_WIDTH);

  let borders = []; // every border of the drawn surfaces
  let active = null; // { filter, onHover, onPick } while enabled
  let hovered = null; // the entry under the pointer
  let hoverLine = null;
  let chosen = []; // [{ patch, border }] highlighted in CHOSEN_COLOR
  const chosenLines = [];
  let press = null; // { id, x, y, moved }

  const find = (patch, border) => borders.find((b) => b.patch === patch && b.border === border) || null;

  function line(entry, mat, order) {
    const g = new LineGeometry();
    g.setPositions(entry.points);
    const l = new Line2(g, mat);
    l.computeLineDistances();
    l.renderOrder = order;
    l.userData.border = { patch: entry.patch, border: entry.border };
    group.add(l);
    return l;
  }
  function drop(l) {
    group.remove(l);
    l.geometry.dispose();
  }

  function drawHover() {
    if (hoverLine) drop(hoverLine);
    hoverLine = hovered ? line(hovered, hoverMaterial, 12) : null;
  }
  function drawChosen() {
    for (const l of chosenLines.splice(0)) drop(l);
    for (const c of chosen) {
      const e = find(c.patch, c.border);
      if (e) chosenLines.push(line(e, chosenMaterial, 11));
    }
  }

  function candidates() {
    return active ? borders.filter((b) => active.filter(b.patch, b.border)) : [];
  }
  function hitAt(x, y, pointerType) {
    const list = candidates();
    if (!list.length) return null;
    const radius = pointerType === 'touch' ? TOUCH_RADIUS : MOUSE_RADIUS;
    return nearestBorder(list, screenProjector(camera, dom), x, y, radius)?.border ?? null;
  }

  function setHovered(entry) {
    if (entry === hovered) return;
    hovered = entry;
    drawHover();
    render();
    active?.onHover(hovered ? pickOf(hovered) : null);
  }

  dom.addEventListener('pointermove', (e) => {
    if (!active) return;
    if (press && e.pointerId === press.id && Math.hypot(e.clientX - press.x, e.clientY - press.y) > CLICK_SLOP) press.moved = true;
    // No hover while a button is down (an orbit) or another tool has the pointer.
    if (e.pointerType === 'touch' || e.buttons !== 0 || busy()) return;
    setHovered(hitAt(e.clientX, e.clientY, e.pointerType));
  });
  dom.addEventListener('pointerleave', (e) => {
    if (active && e.pointerType !== 'touch') setHovered(null);
  });
  dom.addEventListener('pointerdown', (e) => {
    press = active && e.isPrimary && e.button === 0 && !busy() ? { id: e.pointerId, x: e.clientX, y: e.clientY, moved: false } : null;
  });
  dom.addEventListener('pointercancel', () => {
    press = null;
  });
  dom.addEventListener('pointerup', (e) => {
    const p = press;
    press = null;
    if (!active || !p || p.id !== e.pointerId || p.moved) return;
    if (Math.hypot(e.clientX - p.x, e.clientY - p.y) > CLICK_SLOP) return;
    const hit = hitAt(e.clientX, e.clientY, e.pointerType);
    if (!hit) return;
    setHovered(hit); // a tap shows what it picked
    active.onPick(pickOf(hit));
  });

  return {
    /** The drawn patches changed (viewer.setPatches): borders, hover and highlights follow. */
    setPatches(patches) {
      // A surface's border first: where a blend's end lies on it, a tie picks the surface's.
      borders = [...patches.filter((p) => isSurfaceKind(p.kind)), ...patches.filter((p) => !isSurfaceKind(p.kind))].flatMap(bordersOf);
      const h = hovered && find(hovered.patch, hovered.border);
      hovered = h && active?.filter(h.patch, h.border) ? h : null;
      drawHover();
      drawChosen();
    },

    /**
     * Start picking: filter(patchName, border) -> whether that border may be picked;
     * onHover(pick | null) when the border under the pointer changes; onPick(pick) on a
     * click or tap. pick: { patch, border: 't0' | 't1' | 'u0' | 'u1' | 'v0' | 'v1', endpoints: [[x, y, z] at its start, at its end] }.
     */
    enable({ filter = () => true, onHover = () => {}, onPick = () => {} } = {}) {
      active = { filter, onHover, onPick };
      if (hovered && !filter(hovered.patch, hovered.border)) setHovered(null);
    },

    /** Stop picking; the hover line goes, the chosen borders stay. */
    disable() {
      active = null;
      press = null;
      if (hovered) {
        hovered = null;
        drawHover();
        render();
      }
    },

    /** Draw these borders ([{ patch, border }]) as chosen, in CHOSEN_COLOR; [] clears. */
    highlight(picks) {
      chosen = (picks || []).map(({ patch, border }) => ({ patch, border }));
      drawChosen();
      render();
    },

    /** Every border of the drawn surfaces: [{ patch, border, endpoints }]. */
    list() {
      return borders.map(pickOf);
    },

    /** For the tests: { enabled, hovered: { patch, border } | null, chosen: [{ patch, border }] }. */
    state() {
      return {
        enabled: Boolean(active),
        hovered: hovered ? { patch: hovered.patch, border: hovered.border } : null,
        chosen: chosenLines.map((l) => ({ ...l.userData.border })),
      };
    },
  };
}
