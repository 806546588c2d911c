// The "Parameters" folder: one slider per scene parameter, bound to a draft of its value: a
// move reports (name, value) and the edit through the document's door writes the scene (the
// scene is never written before the door has its snapshot); showValues() shows the scene's
// values again after any edit. A remove button beside each, and a row to add one.
// DOM hooks: data-param="<name>" on a slider, data-param-remove="<name>" on its
// button, data-param-new="name" / "value" and data-param-add on the add row.
import { escapeHtml } from './html-text.js';

function removeButton(name, onRemove) {
  const button = document.createElement('button');
  button.type = 'button';
  button.className = 'param-remove';
  button.textContent = '×';
  button.title = `remove the parameter ${name}`; // attributes are never parsed as markup
  button.dataset.paramRemove = name;
  button.addEventListener('click', () => onRemove(name));
  return button;
}

/**
 * Build the folder. handlers: onChange(name, value) after a slider move; onAdd(name, value)
 * (the caller rebuilds the folder when it added one); onRemove(name). The folder's
 * showValues() sets every slider to the scene's value.
 */
export function buildParameterFolder(gui, scene, { onChange, onAdd, onRemove }) {
  const folder = gui.addFolder('Parameters');
  folder.domElement.dataset.folder = 'parameters';
  const params = scene && scene.parameters && typeof scene.parameters === 'object' ? scene.parameters : {};
  const shown = []; // [name, draft, controller]
  for (const [name, p] of Object.entries(params)) {
    if (!p || typeof p !== 'object') continue;
    const { min, max, value, step } = p;
    // Only plain numeric ranges make a slider; the solver reports anything else.
    if (![min, max, value].every(Number.isFinite) || !(max > min)) continue;
    // Without a step of the scene's own, lil-gui's implicit step (range / 1000) moves the
    // slider and a typed value is kept as typed (an explicit step would round it).
    const draft = { value };
    const ctrl = folder
      .add(draft, 'value', min, max, Number.isFinite(step) && step > 0 ? step : undefined)
      .name(escapeHtml(name))
      .onChange((v) => onChange(name, v));
    shown.push([name, draft, ctrl]);
    ctrl.domElement.dataset.param = name; // stable hook for tests and styling
    if (typeof p.label === 'string') ctrl.domElement.title = p.label; // attribute: never parsed
    ctrl.domElement.append(removeButton(name, onRemove));
  }

  folder.showValues = () => {
    for (const [name, draft, ctrl] of shown) {
      const now = params[name]?.value;
      if (Number.isFinite(now) && now !== draft.value) draft.value = now, ctrl.updateDisplay();
    }
  };

  const draft = { name: '', value: 1 };
  const nameCtrl = folder.add(draft, 'name').name(escapeHtml('new name'));
  nameCtrl.domElement.dataset.paramNew = 'name';
  const valueCtrl = folder.add(draft, 'value').name(escapeHtml('new value'));
  valueCtrl.domElement.dataset.paramNew = 'value';
  const actions = { add: () => onAdd(draft.name.trim(), Number(draft.value)) };
  folder.add(actions, 'add').name(escapeHtml('add parameter')).domElement.dataset.paramAdd = '';
  return folder;
}
