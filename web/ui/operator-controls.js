// Per pde patch a folder with sliders for b, c, d per component x, y, z. They start
// from the solver's resolved numbers (scene values may be expressions) and write
// plain numbers back into the scene's operator field.
import { escapeHtml } from './html-text.js';

const FIELDS = ['b', 'c', 'd'];
const AXES = ['x', 'y', 'z'];

// The scene gives no range for operator coefficients: span [0, max(4, 2|v|)] on the
// value's side of zero, so 0 (a degenerate b) is reachable and reported by the solver.
function rangeFor(v) {
  const span = Math.max(4, 2 * Math.abs(v));
  if (v > 0) return [0, span];
  if (v < 0) return [-span, 0];
  return [-span, span];
}

/**
 * Build the folders from solved patches. onChange(patchName, field, axis, value).
 * Returns { update(solvedPatches), destroy() }.
 */
export function buildOperatorFolders(gui, solvedPatches, onChange) {
  const folders = [];
  const models = new Map(); // patch name -> { model, controllers }
  for (const patch of solvedPatches) {
    if (patch.kind !== 'pde' || !patch.operator) continue;
    const folder = gui.addFolder(escapeHtml(`Blend “${patch.name}” operator`));
    folder.domElement.dataset.patch = patch.name;
    const model = {};
    const controllers = [];
    for (const field of FIELDS) {
      for (let i = 0; i < 3; i++) {
        const key = field + AXES[i];
        const v = patch.operator[field][i];
        model[key] = v;
        const [min, max] = rangeFor(v);
        // No explicit step: lil-gui then snaps slider drags to (max-min)/1000 but keeps a
        // typed number exact, so small coefficients such as b = 0.001 stay reachable.
        const ctrl = folder
          .add(model, key, min, max)
          .name(`${field} ${AXES[i]}`)
          .onChange((value) => onChange(patch.name, field, AXES[i], value));
        ctrl.domElement.dataset.operator = key;
        controllers.push(ctrl);
      }
    }
    folders.push(folder);
    models.set(patch.name, { model, controllers });
  }

  return {
    /** Show the resolved numbers of a later solve (expressions follow parameters). */
    update(patches) {
      for (const patch of patches) {
        const entry = models.get(patch.name);
        if (!entry || !patch.operator) continue;
        for (const field of FIELDS) {
          for (let i = 0; i < 3; i++) entry.model[field + AXES[i]] = patch.operator[field][i];
        }
        // updateDisplay does not fire onChange, so this cannot loop back into a solve.
        for (const c of entry.controllers) c.updateDisplay();
      }
    },
    destroy() {
      for (const f of folders) f.destroy();
    },
  };
}
