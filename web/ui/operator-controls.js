// Per pde patch a folder (data-patch="<name>"): the solution method, then per
// coordinate x, y, z its operator's order and coefficients. Controls start from the
// solver's resolved numbers (scene values may be expressions) and write plain numbers
// back through the handlers, which edit the scene.
import { escapeHtml } from './html-text.js';
import { AXES } from '../state/operator-edit.js';
import { buildAxisControls } from './axis-controls.js';
import { buildMethodControls } from './method-controls.js';

/**
 * Build the folders from solved patches. handlers:
 *   methodOf(patch) -> the scene's method ("auto" if none)
 *   onParam(patch, axis, name, value)
 *   onOrder(patch, axis, order) -> the coordinate's new coefficients, or null
 *   onMethod(patch, method)
 * Returns { update(solvedPatches), destroy() }.
 */
export function buildOperatorFolders(gui, solvedPatches, handlers) {
  const folders = [];
  const views = new Map(); // patch name -> { method, axes: { x, y, z } }
  for (const patch of solvedPatches) {
    if (patch.kind !== 'pde' || !patch.operator) continue;
    const name = patch.name;
    const folder = gui.addFolder(escapeHtml(`Blend “${name}”`));
    folder.domElement.dataset.patch = name;
    const method = buildMethodControls(folder, patch, handlers.methodOf(name), (m) => handlers.onMethod(name, m));
    const axes = {};
    for (const axis of AXES) {
      axes[axis] = buildAxisControls(folder, axis, patch.operator[axis], {
        onOrder: (order) => handlers.onOrder(name, axis, order),
        onParam: (param, value) => handlers.onParam(name, axis, param, value),
      });
    }
    folders.push(folder);
    views.set(name, { method, axes });
  }

  return {
    /** Reflect a later solve: resolved numbers, orders and the method used. */
    update(patches) {
      for (const patch of patches) {
        const view = views.get(patch.name);
        if (!view || !patch.operator) continue;
        view.method.update(patch);
        for (const axis of AXES) view.axes[axis].update(patch.operator[axis]);
      }
    },
    destroy() {
      for (const f of folders) f.destroy();
    },
  };
}
