// Editing one control point of a bezier patch's initial net: a toggle for picking and
// dragging in the view, the point's indices i, j, what the point does (fixed ring or
// free), and its x, y, z as number fields (typed, or dragged up and down on the field).
// DOM hooks: data-control-point="<patch>" on the folder, data-cp="edit" | "i" | "j" |
// "role" | "x" | "y" | "z" on the controls.
import { escapeHtml } from './html-text.js';
import { AXES, controlPointRole } from '../state/control-net-edit.js';

const DRAG_STEP = 0.01; // per pixel of a drag on a field; typed numbers stay exact

function roleText(role, gamma) {
  if (role === 'fixed') return 'fixed ring: moves the border';
  return gamma > 0 ? 'free: pulls the surface through γ' : 'free: no effect while γ = 0';
}

const within = (k, n, fallback) => (Number.isInteger(k) && k >= 0 && k < n ? k : fallback);

/**
 * rows, cols: the net's size; energy: "membrane" | "thin-plate"; pointOf(i, j) -> [x, y, z];
 * onEditMode(on); onSelect(i, j); onCoordinate(i, j, axis, value); start: { i, j, edit } of
 * the editor this one replaces (a rebuild after an undo), if any.
 * Returns { select(i, j), setEditMode(on), refresh(gamma?), current() }.
 */
export function buildControlPointControls(parent, { patchName, rows, cols, energy, pointOf, onEditMode, onSelect, onCoordinate, start = null }) {
  const folder = parent.addFolder(escapeHtml('Edit the initial net'));
  folder.domElement.dataset.controlPoint = patchName;
  // Start in the middle of the net: an interior point, the one most edits begin with.
  const model = {
    edit: Boolean(start?.edit), i: within(start?.i, rows, rows >> 1), j: within(start?.j, cols, cols >> 1),
    role: '', x: 0, y: 0, z: 0,
  };
  let gamma = 0;

  const hook = (ctrl, name) => {
    ctrl.domElement.dataset.cp = name;
    return ctrl;
  };
  const edit = hook(folder.add(model, 'edit').name(escapeHtml('pick & drag in the view')), 'edit')
    .onChange((on) => onEditMode(on));
  edit.domElement.title = 'shows the initial net; click one of its points to pick it, drag the arrows to move it';
  const indices = ['i', 'j'].map((key) => hook(
    folder.add(model, key, 0, (key === 'i' ? rows : cols) - 1, 1)
      .name(escapeHtml(key))
      .onChange(() => {
        show();
        onSelect(model.i, model.j);
      }),
    key));
  const role = hook(folder.add(model, 'role').name(escapeHtml('acts as')).disable(), 'role');
  const coords = AXES.map((axis) => hook(
    folder.add(model, axis).step(DRAG_STEP, false).name(escapeHtml(axis))
      .onChange((value) => {
        if (Number.isFinite(value)) onCoordinate(model.i, model.j, axis, value);
      }),
    axis));

  // Show point (i, j) as the scene has it; updateDisplay fires no onChange, so no loop.
  function show() {
    const p = pointOf(model.i, model.j);
    AXES.forEach((axis, a) => {
      model[axis] = p[a];
    });
    model.role = roleText(controlPointRole(model.i, model.j, rows, cols, energy), gamma);
    for (const c of [...indices, role, ...coords]) c.updateDisplay();
  }
  show();
  folder.close();

  return {
    /** Point (i, j) was picked elsewhere (in the view). */
    select(i, j) {
      model.i = i;
      model.j = j;
      folder.open();
      show();
    },
    setEditMode(on) {
      model.edit = on;
      edit.updateDisplay();
      if (on) folder.open();
    },
    /** After a solve or a drag: the point's numbers, and the role under the solved γ. */
    refresh(solvedGamma = gamma) {
      gamma = solvedGamma;
      show();
    },
    current() {
      return { i: model.i, j: model.j, edit: model.edit };
    },
  };
}
