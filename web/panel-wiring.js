// The control panel, its every handler an edit through the document's door
// (web/state/document.js): the door re-solves, records the undo step and updates the link.
import { createPanel } from './ui/panel.js';

/** { doc, share, bezier } -> the panel (web/ui/panel.js). */
export function createPanelWiring({ doc, share, bezier }) {
  const { state } = doc;
  const apply = (name, run, more = {}) => doc.apply({ name, run, ...more }).ok;

  const panel = createPanel({
    grid: state.grid,
    onGridChange: (grid) => apply('change the grid', (s) => s.setGrid(grid)),
    onShare: () => share().copy(),
    parameterHandlers: {
      onChange: (name, value) => apply('change a parameter', (s) => s.setParameter(name, value)),
      onAdd: (name, value) => apply('add the parameter', (s) => s.addParameter(name, value), { structure: true }),
      // Allowed even while an expression uses it: the solver's error then says where.
      onRemove: (name) => apply('remove the parameter', (s) => s.removeParameter(name), { structure: true }),
    },
    operatorHandlers: {
      methodOf: (patch) => state.methodOf(patch),
      onParam: (patch, axis, name, value) => apply('change the operator', (s) => s.setOperatorParam(patch, axis, name, value)),
      onOrder: (patch, axis, order) => {
        let params = null;
        apply('change the order', (s) => {
          params = s.setOperatorOrder(patch, axis, order);
        }, { solve: 'now' });
        if (params) panel.setOrder(patch, axis, order);
        return params;
      },
      onMethod: (patch, method) => apply('change the method', (s) => s.setMethod(patch, method)),
    },
    bezierHandlers: bezier.panelHandlers,
    endHandlers: {
      // A continuity may raise the orders.
      onField: (patch, end, key, value, typed) =>
        apply('change the end', (s) => s.setEndField(patch, end, key, value), { solve: typed ? 'typed' : 'now' }),
      onAttach: (patch, end) => apply('attach the end', (s) => s.attachEnd(patch, end), { ends: true }),
      onDetach: (patch, end, derived) => apply('detach the end', (s) => s.detachEnd(patch, end, derived), { ends: true }),
    },
    onExpression: (patch, field, text) => apply('change the expression', (s) => s.setExpression(patch, field, text), { solve: 'typed' }),
  });
  return panel;
}
