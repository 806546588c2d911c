// The control panel, its every handler an edit through the document's door
// (web/state/document.js): the door re-solves, records the undo step and updates the link.
import { createPanel } from '../ui/panel.js';
import { edits } from '../state/edits.js';

/** The context's { doc, bezier } (its share is read when the link is copied) -> the panel (web/ui/panel.js). */
export function createPanelFeature(ctx) {
  const { doc, bezier } = ctx;
  const { state } = doc;
  const apply = (edit) => doc.apply(edit).ok;

  const panel = createPanel({
    grid: state.grid,
    onGridChange: (grid) => apply(edits.setGrid(grid)),
    onShare: () => ctx.share.copy(),
    parameterHandlers: {
      onChange: (name, value) => apply(edits.setParameter(name, value)),
      onAdd: (name, value) => apply(edits.addParameter(name, value)),
      onRemove: (name) => apply(edits.removeParameter(name)),
    },
    operatorHandlers: {
      methodOf: (patch) => state.methodOf(patch),
      onParam: (patch, axis, name, value) => apply(edits.setOperatorParam(patch, axis, name, value)),
      onOrder: (patch, axis, order) => {
        const r = doc.apply(edits.setOperatorOrder(patch, axis, order));
        const params = r.ok ? r.result : null;
        if (params) panel.setOrder(patch, axis, order);
        return params;
      },
      onMethod: (patch, method) => apply(edits.setMethod(patch, method)),
    },
    bezierHandlers: bezier.panelHandlers,
    endHandlers: {
      onField: (patch, end, key, value, typed) => apply(edits.setEndField(patch, end, key, value, typed)),
      onAttach: (patch, end) => apply(edits.attachEnd(patch, end)),
      onDetach: (patch, end, derived) => apply(edits.detachEnd(patch, end, derived)),
    },
    onExpression: (patch, field, text) => apply(edits.setExpression(patch, field, text)),
  });
  return panel;
}
