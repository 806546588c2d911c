// One coordinate's operator inside a blend's folder: an order selector and one slider
// per coefficient, named as the solver names them (s, t / b, c, d / a / coefficients[k]).
// DOM hooks (tests, styling): data-order="<axis>" on the selector,
// data-operator="<axis>.<name>" on each slider (e.g. "x.b", "z.coefficients[0]").
import { escapeHtml } from './html-text.js';
import { ORDERS } from '../state/operator-edit.js';

// The scene gives no range for operator coefficients: span [0, max(4, 2|v|)] on the
// value's side of zero, so 0 (a degenerate leading coefficient) is reachable and
// reported by the solver.
export function rangeFor(v) {
  const span = Math.max(4, 2 * Math.abs(v));
  if (v > 0) return [0, span];
  if (v < 0) return [-span, 0];
  return [-span, span];
}

const namesKey = (params) => Object.keys(params).join('\0');

/**
 * Build the controls of coordinate `axis` into `parent` (a lil-gui folder) from the
 * solver's { order, params }. onOrder(order) returns the new coefficients (or null when
 * nothing changed); onParam(name, value). Returns { update({ order, params }) }.
 */
export function buildAxisControls(parent, axis, op, { onOrder, onParam }) {
  const folder = parent.addFolder(escapeHtml(axis));
  folder.domElement.dataset.axis = axis;

  const model = { order: op.order };
  const orderOptions = {};
  for (const o of ORDERS) orderOptions[escapeHtml(String(o))] = o;
  const orderCtrl = folder
    .add(model, 'order', orderOptions)
    .name(escapeHtml('order'))
    .onChange((order) => {
      const params = onOrder(order);
      if (params) showParams(params);
    });
  orderCtrl.domElement.dataset.order = axis;

  let values = {}; // the sliders' model: name -> number
  let sliders = [];
  let shownNames = '';

  // Coefficient names depend on the order: rebuild the sliders (after the selector).
  function showParams(params) {
    for (const s of sliders) s.destroy();
    values = { ...params };
    shownNames = namesKey(params);
    sliders = Object.entries(params).map(([name, v]) => {
      const [min, max] = rangeFor(v);
      // No explicit step: lil-gui then snaps slider drags to (max-min)/1000 but keeps a
      // typed number exact, so small coefficients such as b = 0.001 stay reachable.
      const ctrl = folder
        .add(values, name, min, max)
        .name(escapeHtml(name))
        .onChange((value) => onParam(name, value));
      ctrl.domElement.dataset.operator = `${axis}.${name}`;
      return ctrl;
    });
  }
  showParams(op.params);

  return {
    /** Show the resolved numbers of a later solve (expressions follow parameters). */
    update(solved) {
      model.order = solved.order;
      // updateDisplay does not fire onChange, so this cannot loop back into a solve.
      orderCtrl.updateDisplay();
      if (namesKey(solved.params) !== shownNames) {
        showParams(solved.params);
        return;
      }
      Object.assign(values, solved.params);
      for (const s of sliders) s.updateDisplay();
    },
  };
}
