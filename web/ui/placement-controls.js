// The panel's placement folder of the selected surface: move (x, y, z), turn (degrees about
// x, y, z, three.js's Euler order XYZ) and scale by numbers, and the view's gizmo mode
// (web/viewer/placement-gizmo.js). Scene version 4's `placement` (docs/scene-format-v4.md).
import { escapeHtml } from './html-text.js';

const MODES = { off: 'off', move: 'translate', turn: 'rotate', scale: 'scale' };

const numberOr = (x, fallback) => (typeof x === 'number' && Number.isFinite(x) ? x : fallback);

/** handlers: { onPlacement(name, placement), onMode(mode | null) }. Returns { update, destroy }. */
export function buildPlacementFolder(gui, name, placement, handlers, mode = 'off') {
  const folder = gui.addFolder('Placement');
  folder.$title.textContent = `Placement of ${name}`; // lil-gui's title() writes markup
  folder.domElement.classList.add('placement-folder');
  const p = placement || {};
  const t = p.translate || [0, 0, 0], r = p.rotate || [0, 0, 0];
  const v = {
    x: numberOr(t[0], 0), y: numberOr(t[1], 0), z: numberOr(t[2], 0),
    rx: numberOr(r[0], 0), ry: numberOr(r[1], 0), rz: numberOr(r[2], 0),
    scale: numberOr(p.scale, 1),
    gizmo: Object.keys(MODES).find((k) => MODES[k] === mode) ?? 'off',
  };
  const write = () => handlers.onPlacement(name, { translate: [v.x, v.y, v.z], rotate: [v.rx, v.ry, v.rz], scale: v.scale });
  folder.add(v, 'gizmo', Object.keys(MODES)).name('in the view').onChange((k) => handlers.onMode(MODES[k] === 'off' ? null : MODES[k]))
    .domElement.dataset.placement = 'gizmo';
  for (const [key, label] of [['x', 'move x'], ['y', 'move y'], ['z', 'move z']]) {
    folder.add(v, key).name(label).step(0.01).onFinishChange(write).domElement.dataset.placement = key;
  }
  for (const [key, label] of [['rx', 'turn about x (°)'], ['ry', 'turn about y (°)'], ['rz', 'turn about z (°)']]) {
    folder.add(v, key, -180, 180, 0.5).name(escapeHtml(label)).onFinishChange(write).domElement.dataset.placement = key;
  }
  folder.add(v, 'scale', 0.05, 10, 0.01).name('scale').onFinishChange(write).domElement.dataset.placement = 'scale';
  return {
    folder,
    /** The placement changed elsewhere (the gizmo, undo): show its numbers. */
    update(next) {
      const q = next || {};
      const tt = q.translate || [0, 0, 0], rr = q.rotate || [0, 0, 0];
      Object.assign(v, { x: numberOr(tt[0], 0), y: numberOr(tt[1], 0), z: numberOr(tt[2], 0),
        rx: numberOr(rr[0], 0), ry: numberOr(rr[1], 0), rz: numberOr(rr[2], 0), scale: numberOr(q.scale, 1) });
      for (const c of folder.controllers) c.updateDisplay();
    },
    destroy: () => folder.destroy(),
  };
}
