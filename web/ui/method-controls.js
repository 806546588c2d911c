// A blend's solution method: a selector over the methods the solver lists for the
// patch (patch.methods) and a read-only line with the method that was actually used
// (patch.method; "auto" resolves to one of the others).
// DOM hooks: data-method="<patch>" on the selector, data-method-used="<patch>" on the line.
import { escapeHtml } from './html-text.js';

// The scene's own choice stays listed even if the solver no longer offers it, because
// lil-gui shows a value missing from its options as raw markup.
function optionsFor(methods, current) {
  const list = methods.includes(current) ? methods : [...methods, current];
  const options = {};
  for (const m of list) {
    let label = escapeHtml(m);
    while (label in options) label += ' '; // labels are keys: keep them unique
    options[label] = m;
  }
  return options;
}

/**
 * Add the method controls to `folder` from a solved pde patch. `chosen` is the scene's
 * method ("auto" when it names none); onMethod(method). Returns { update(solvedPatch) }.
 */
export function buildMethodControls(folder, patch, chosen, onMethod) {
  const model = { method: chosen, used: patch.method };
  let shownMethods = patch.methods.join('\0');

  const addSelector = (methods) => {
    const ctrl = folder
      .add(model, 'method', optionsFor(methods, model.method))
      .name(escapeHtml('method'))
      .onChange(onMethod);
    ctrl.domElement.dataset.method = patch.name;
    return ctrl;
  };
  let selector = addSelector(patch.methods);

  // A disabled text field: lil-gui sets an input's value, which is never parsed as markup.
  const used = folder.add(model, 'used').name(escapeHtml('solved by')).disable();
  used.domElement.dataset.methodUsed = patch.name;

  return {
    update(solved) {
      model.used = solved.method;
      used.updateDisplay();
      const methods = solved.methods.join('\0');
      if (methods === shownMethods) return;
      // lil-gui cannot change a selector's options in place: replace it and move the
      // new one back to the top of the folder.
      shownMethods = methods;
      const next = addSelector(solved.methods);
      selector.destroy();
      selector = next;
      folder.$children.insertBefore(selector.domElement, folder.$children.firstChild);
    },
  };
}
