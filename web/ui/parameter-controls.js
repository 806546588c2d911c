// The "Parameters" folder: one slider per scene parameter, bound straight to
// scene.parameters[name].value so the scene object stays the single source of truth,
// a remove button beside each, and a row to add one (name + value).
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
 * Build the folder. handlers: onChange() after a slider move; onAdd(name, value) (the
 * caller rebuilds the folder when it added one); onRemove(name).
 */
export function buildParameterFolder(gui, scene, { onChange, onAdd, onRemove }) {
  const folder = gui.addFolder('Parameters');
  folder.domElement.dataset.folder = 'parameters';
  const params = scene && scene.parameters && typeof scene.parameters === 'object' ? scene.parameters : {};
  for (const [name, p] of Object.entries(params)) {
    if (!p || typeof p !== 'object') continue;
    const { min, max, value, step } = p;
    // Only plain numeric ranges make a slider; the solver reports anything else.
    if (![min, max, value].every(Number.isFinite) || !(max > min)) continue;
    // Without a step of the scene's own, lil-gui's implicit step (range / 1000) moves the
    // slider and a typed value is kept as typed (an explicit step would round it).
    const ctrl = folder
      .add(p, 'value', min, max, Number.isFinite(step) && step > 0 ? step : undefined)
      .name(escapeHtml(name))
      .onChange(onChange);
    ctrl.domElement.dataset.param = name; // stable hook for tests and styling
    if (typeof p.label === 'string') ctrl.domElement.title = p.label; // attribute: never parsed
    ctrl.domElement.append(removeButton(name, onRemove));
  }

  const draft = { name: '', value: 1 };
  const nameCtrl = folder.add(draft, 'name').name(escapeHtml('new name'));
  nameCtrl.domElement.dataset.paramNew = 'name';
  const valueCtrl = folder.add(draft, 'value').name(escapeHtml('new value'));
  valueCtrl.domElement.dataset.paramNew = 'value';
  const actions = { add: () => onAdd(draft.name.trim(), Number(draft.value)) };
  folder.add(actions, 'add').name(escapeHtml('add parameter')).domElement.dataset.paramAdd = '';
  return folder;
}
