// Text fields for a version-2 scene's functions: per blend ("pde" patch) and
// coordinate the boundary slots u0/u1 × derivative order (order/2 of each) and the
// force; per "surface" patch its x, y, z in t and v. Edits go through onEdit; solver
// messages come back through showSolveError and land beside the field they name.
// An end given by reference (version 3) has no slots: the solver derives them and would
// refuse typed ones. A one-line note points to its Ends folder instead.
import { escapeHtml } from './html-text.js';
import { buildExpressionField, fieldForMessage } from './expression-field.js';
import {
  AXES, ENDS, boundaryPath, forcePath, surfacePath, boundarySlot, forceOf, surfaceCoordinate, RANGE_ENDS, surfaceRangeEnd, nurbsSummary,
} from '../state/expression-edit.js';
import { isByReference } from '../state/ends-edit.js';

const PRIMES = ['', 'ᵤ', 'ᵤᵤ', 'ᵤᵤᵤ'];
const slotLabel = (axis, end, k) => `${axis}${PRIMES[k] ?? `^(${k})`}(${end === 'u0' ? 0 : 1})`;
const slotTitle = (axis, end, k) =>
  `${k === 0 ? axis : `∂${k > 1 ? `^${k}` : ''}${axis}/∂u${k > 1 ? `^${k}` : ''}`} at u = ${end === 'u0' ? 0 : 1}, a function of v`;

/**
 * scene: the scene object (read for the current text); solved: the solver's patches
 * (for each blend coordinate's resolved order); onEdit(patchName, field, text) where
 * field is { kind: 'boundary', axis, end, k } | { kind: 'force', axis } | { kind: 'surface', axis }.
 * Returns { setOrder(patchName, axis, order), update(solved), showSolveError(msg), elements(), destroy() }.
 */
export function buildExpressionFolders(gui, scene, solved, onEdit) {
  const folders = [];
  const axisViews = new Map(); // "patch\0axis" -> { folder, fields, count, patch, index }
  const fields = () => [...surfaceFields, ...[...axisViews.values()].flatMap((v) => v.fields)];
  const surfaceFields = [];
  let lastEdited = null;

  const edit = (patchName, field, fieldView) => (text) => {
    lastEdited = fieldView();
    onEdit(patchName, field, text);
  };

  function fillAxis(view, axis, count) {
    for (const f of view.fields) f.destroy();
    view.fields = [];
    view.count = count;
    const { patch, index } = view;
    for (const end of ENDS) {
      if (isByReference(patch, end)) continue;
      for (let k = 0; k < count; k++) {
        const f = buildExpressionField(view.folder, {
          label: slotLabel(axis, end, k), title: slotTitle(axis, end, k), path: boundaryPath(index, axis, end, k),
          value: boundarySlot(patch, axis, end, k), onEdit: edit(patch.name, { kind: 'boundary', axis, end, k }, () => f),
        });
        view.fields.push(f);
      }
    }
    const force = buildExpressionField(view.folder, {
      label: `f${axis}(u,v)`, title: `force on ${axis}, a function of u and v; empty for none`, path: forcePath(index, axis),
      value: forceOf(patch, axis), onEdit: edit(patch.name, { kind: 'force', axis }, () => force),
    });
    view.fields.push(force);
  }

  const patches = Array.isArray(scene.patches) ? scene.patches : [];
  patches.forEach((patch, index) => {
    if (!patch || typeof patch !== 'object') return;
    if (patch.kind === 'pde') {
      const result = solved.find((p) => p.name === patch.name && p.operator);
      if (!result) return;
      const folder = gui.addFolder(escapeHtml(`Functions “${patch.name}”`));
      folder.domElement.classList.add('expr-folder');
      folder.domElement.dataset.functions = patch.name;
      for (const end of ENDS.filter((e) => isByReference(patch, e))) {
        const line = document.createElement('div');
        line.className = 'end-note';
        line.dataset.endNote = end;
        line.textContent = `${end}: given by reference (Ends of “${patch.name}”)`; // text: never markup
        folder.$children.append(line);
      }
      for (const axis of AXES) {
        const view = { folder: folder.addFolder(escapeHtml(axis)), fields: [], count: 0, patch, index };
        view.folder.domElement.dataset.axis = axis;
        fillAxis(view, axis, result.operator[axis].order / 2);
        axisViews.set(`${patch.name}\0${axis}`, view);
      }
      folders.push(folder);
    } else if (patch.kind === 'surface') {
      const folder = gui.addFolder(escapeHtml(`Surface “${patch.name}”`));
      folder.domElement.classList.add('expr-folder');
      folder.domElement.dataset.surface = patch.name;
      if (patch.nurbs) {  // data from a file (pdesurf import): said, not typed
        const line = document.createElement('div');
        line.className = 'end-note';
        line.dataset.nurbs = patch.name;
        line.textContent = nurbsSummary(patch); // text: never markup
        folder.$children.append(line);
      } else {
        for (const axis of AXES) {
          const f = buildExpressionField(folder, {
            label: `${axis}(t,v)`, title: `${axis} of the surface, a function of t and v`, path: surfacePath(index, axis),
            value: surfaceCoordinate(patch, axis), onEdit: edit(patch.name, { kind: 'surface', axis }, () => f),
          });
          surfaceFields.push(f);
        }
      }
      for (const [key, k, label] of RANGE_ENDS) {
        const f = buildExpressionField(folder, {
          label, title: `the surface's ${key}[${k}], a number or an expression in the parameters`, path: `patches[${index}].${key}[${k}]`,
          value: surfaceRangeEnd(patch, key, k), onEdit: edit(patch.name, { kind: 'range', key, k }, () => f),
        });
        surfaceFields.push(f);
      }
      folders.push(folder);
    }
  });

  const api = {
    /** A coordinate's order changed: order/2 slots per end (the scene was already fitted). */
    setOrder(patchName, axis, order) {
      const view = axisViews.get(`${patchName}\0${axis}`);
      if (view && view.count !== order / 2) fillAxis(view, axis, order / 2);
    },
    /** After a good solve: follow the resolved orders and clear every message. */
    update(solvedPatches) {
      for (const p of solvedPatches) {
        if (!p.operator) continue;
        for (const axis of AXES) api.setOrder(p.name, axis, p.operator[axis].order);
      }
      for (const f of fields()) f.showError(null);
      lastEdited = null; // a later failure is not this edit's
    },
    /** After a failed solve: the message beside the field it is about (if any). */
    showSolveError(message) {
      const target = fieldForMessage(fields(), message, lastEdited);
      for (const f of fields()) f.showError(f === target ? message : null);
      return target ? target.path : null;
    },
    /** The folders' root elements, in order (to put rebuilt folders where the old ones were). */
    elements() {
      return folders.map((f) => f.domElement);
    },
    destroy() {
      for (const f of folders) f.destroy();
    },
  };
  return api;
}
