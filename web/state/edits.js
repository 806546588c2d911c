// The catalogue of the page's edits: every change of the scene or the grid is made by one of
// these factories and handed to the document's door (./document.js). Each edit has a stable
// `type` (code branches on it, never on `name`, the words the status line shows), its `run`
// (the only place the scene is written) and how it is solved and shown:
//   solve: 'now' (default) | 'typed' (once the keys pause) | 'none'
//   structure: patches or parameters added, removed or renamed (folders rebuilt)
//   ends: an end attached or detached (its folders change shape)
//   checked: the solver is the judge (refused, the scene goes back)
//   build: a building edit (its answer shows in the Build folder)
//
// These run through the scene state's own methods (./scene-state.js), so this module imports
// nothing (the page's first chunk carries it); the building edits are in ./build-edits.js.

export const edits = Object.freeze({
  // Parameters and the grid.
  setParameter: (name, value) => ({ type: 'set-parameter', name: 'change a parameter', run: (s) => s.setParameter(name, value) }),
  addParameter: (name, value) => ({ type: 'add-parameter', name: 'add the parameter', run: (s) => s.addParameter(name, value), structure: true }),
  // Allowed even while an expression uses it: the solver's error then says where.
  removeParameter: (name) => ({ type: 'remove-parameter', name: 'remove the parameter', run: (s) => s.removeParameter(name), structure: true }),
  setGrid: (grid) => ({ type: 'set-grid', name: 'change the grid', run: (s) => s.setGrid(grid) }),

  // A patch's operator, method, ends and expressions.
  setOperatorParam: (patch, axis, param, value) => ({ type: 'operator-param', name: 'change the operator', run: (s) => s.setOperatorParam(patch, axis, param, value) }),
  // Its result: the new order's parameters (a continuity may raise the orders).
  setOperatorOrder: (patch, axis, order) => ({ type: 'operator-order', name: 'change the order', run: (s) => s.setOperatorOrder(patch, axis, order) }),
  setMethod: (patch, method) => ({ type: 'method', name: 'change the method', run: (s) => s.setMethod(patch, method) }),
  setEndField: (patch, end, key, value, typed) => ({ type: 'end-field', name: 'change the end', run: (s) => s.setEndField(patch, end, key, value), solve: typed ? 'typed' : 'now' }),
  attachEnd: (patch, end) => ({ type: 'attach-end', name: 'attach the end', run: (s) => s.attachEnd(patch, end), ends: true }),
  detachEnd: (patch, end, derived) => ({ type: 'detach-end', name: 'detach the end', run: (s) => s.detachEnd(patch, end, derived), ends: true }),
  setExpression: (patch, field, text) => ({ type: 'expression', name: 'change the expression', run: (s) => s.setExpression(patch, field, text), solve: 'typed' }),
  // A Bézier patch's initial control net: write(state) changes it (features/bezier.js).
  controlNet: (write) => ({ type: 'control-net', name: 'edit the control net', run: write }),
});
