// Per bezier patch a folder "Bézier “name”" (data-bezier="<name>"): the solve's energy
// and normal misfit (read-only, refreshed after every solve), λ and γ sliders when the
// scene gives them as plain numbers (parameter expressions have their sliders under
// Parameters), toggles for the solved net, the initial net and the guiding normals,
// λ weights by region (discrete fields only) and the initial-net editor.
// DOM hooks: data-bezier-readout="energy" | "misfit", data-bezier-number="lambda" |
// "gamma", data-bezier-toggle="solvedNet" | "initialNet" | "normals".
import { escapeHtml } from './html-text.js';
import { buildRegionWeightControls } from './region-weight-controls.js';
import { buildControlPointControls } from './control-point-controls.js';
import { netSizeOf } from '../state/control-net-edit.js';

const TOGGLES = [
  ['solvedNet', 'solved control net'],
  ['initialNet', 'initial control net'],
  ['normals', 'guiding normals'],
];
const NUMBERS = [
  ['lambda', 'λ', 'weight of the normal field'],
  ['gamma', 'γ', 'weight of the initial surface'],
];

const readout = (x) => (Number.isFinite(x) ? x.toPrecision(6) : '—');

// The scene gives no range: [0, max(100, 2v)] keeps the value mid-slider and 0 reachable.
const rangeFor = (v) => [0, Math.max(100, 2 * Math.abs(v))];

// carried: { shown, point } of the folder this one replaces (a rebuild after an undo), or undefined.
function buildFolder(gui, patch, solved, h, carried) {
  const name = patch.name;
  const folder = gui.addFolder(escapeHtml(`Bézier “${name}”`));
  folder.domElement.dataset.bezier = name;

  // Disabled text fields: lil-gui sets an input's value, which is never parsed as markup.
  const numbers = { energy: '', misfit: '' };
  const readouts = [['energy', 'energy'], ['misfit', 'normal misfit']].map(([key, label]) => {
    const c = folder.add(numbers, key).name(escapeHtml(label)).disable();
    c.domElement.dataset.bezierReadout = key;
    return c;
  });

  const values = {};
  for (const [key, label, title] of NUMBERS) {
    const v = patch[key] === undefined ? 0 : patch[key]; // absent reads as 0 in the solver
    if (typeof v !== 'number' || !Number.isFinite(v)) continue;
    values[key] = v;
    const [min, max] = rangeFor(v);
    const c = folder.add(values, key, min, max).name(escapeHtml(label)).onChange((x) => h.onNumber(name, key, x));
    c.domElement.dataset.bezierNumber = key;
    c.domElement.title = title;
  }

  const shown = {};
  for (const [key, label] of TOGGLES) {
    shown[key] = Boolean(carried?.shown[key]);
    folder.add(shown, key).name(escapeHtml(label)).onChange((on) => h.onOverlay(name, key, on))
      .domElement.dataset.bezierToggle = key;
  }

  buildRegionWeightControls(folder, patch, (regions) => h.onRegionWeights(name, regions));

  const [rows, cols] = solved.netSize;
  const point = buildControlPointControls(folder, {
    patchName: name, rows, cols, energy: patch.energy,
    pointOf: (i, j) => h.pointOf(name, i, j),
    onEditMode: (on) => h.onEditMode(name, on, point.current()),
    onSelect: (i, j) => h.onSelect(name, i, j),
    onCoordinate: (i, j, axis, value) => h.onCoordinate(name, i, j, axis, value),
    start: carried?.point,
  });

  const view = {
    folder,
    point,
    update(s) {
      numbers.energy = readout(s.energy);
      numbers.misfit = readout(s.normalMisfit);
      for (const c of readouts) c.updateDisplay();
      point.refresh(s.gamma);
    },
    /** What the user set that is not in the scene: the overlay toggles and the edited point. */
    ui: () => ({ shown: { ...shown }, point: point.current() }),
  };
  view.update(solved);
  return view;
}

/**
 * Build the folders from the scene's bezier patches that solved. handlers:
 *   onOverlay(patch, key, on); onNumber(patch, 'lambda' | 'gamma', value);
 *   onRegionWeights(patch, regions); pointOf(patch, i, j) -> [x, y, z];
 *   onEditMode(patch, on, { i, j }); onSelect(patch, i, j); onCoordinate(patch, i, j, axis, value)
 * carried: the ui() of the folders these replace for the same scene (after an undo), or null.
 * Returns { update(solved), select(patch, i, j), setEditMode(patch, on), refreshPoint(patch), ui(), destroy() }.
 */
export function buildBezierFolders(gui, scene, solvedPatches, handlers, carried = null) {
  const views = new Map();
  for (const patch of Array.isArray(scene?.patches) ? scene.patches : []) {
    if (!patch || patch.kind !== 'bezier' || !netSizeOf(patch)) continue;
    const solved = solvedPatches.find((p) => p.name === patch.name && p.kind === 'bezier');
    if (solved) views.set(patch.name, buildFolder(gui, patch, solved, handlers, carried?.get(patch.name)));
  }
  return {
    update(patches) {
      for (const p of patches) views.get(p.name)?.update(p);
    },
    select(name, i, j) {
      views.get(name)?.point.select(i, j);
    },
    setEditMode(name, on) {
      views.get(name)?.point.setEditMode(on);
    },
    refreshPoint(name) {
      views.get(name)?.point.refresh();
    },
    /** patch name -> { shown, point }: handed to the folders that replace these. */
    ui() {
      return new Map([...views].map(([name, v]) => [name, v.ui()]));
    },
    destroy() {
      for (const v of views.values()) v.folder.destroy();
    },
  };
}
