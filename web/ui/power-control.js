// An end's power (docs/blends-by-reference.md): a slider (0.1 to 4) with its number box
// when the scene's power is a number, and ƒ to write it as an expression instead; a text
// field when it is an expression (a parameter's name whose slider is in Parameters, or a
// function of v), and # to replace it by its current value (offered for a number or a
// parameter's name: the only expressions with one value the page knows).
// DOM hooks: data-end-field="power" on the control, "power-expression" / "power-number" on
// the small button beside it.
import { escapeHtml } from './html-text.js';
import { buildExpressionField } from './expression-field.js';
import { powerValue } from '../state/ends-edit.js';

export const POWER_RANGE = [0.1, 4];

const TITLE = 'how far the blend carries the surface\'s direction (1: a tangent as long as the gap)';

/** A small button inside a controller's row (like the parameter remove buttons). */
function rowButton(root, { text, title, hook, onClick }) {
  const button = document.createElement('button');
  button.type = 'button';
  button.className = 'end-row-button';
  button.textContent = text;
  button.title = title;
  button.dataset.endField = hook;
  button.addEventListener('click', onClick);
  root.querySelector('.widget').after(button);
  return button;
}

/**
 * Add the power control to `folder`. spec: { scene, power (the scene's value), path (the
 * solver's name for it), onPower(value, typed), onKind() (number <-> expression: the caller
 * rebuilds) }. Returns { field (the expression field, or null for a slider), sync() }.
 */
export function buildPowerControl(folder, { scene, power, path, onPower, onKind }) {
  if (typeof power === 'number') {
    const model = { power };
    const ctrl = folder.add(model, 'power', ...POWER_RANGE).name(escapeHtml('power')).onChange((p) => onPower(p, false));
    ctrl.domElement.dataset.endField = 'power';
    ctrl.domElement.title = TITLE;
    rowButton(ctrl.domElement, {
      text: 'ƒ', hook: 'power-expression', title: 'write the power as an expression (a parameter\'s name, or a function of v)',
      onClick: () => {
        onPower(String(model.power), false);
        onKind();
      },
    });
    return { field: null, sync() {} };
  }

  let text = power;
  const field = buildExpressionField(folder, {
    label: 'power', title: `${TITLE}; an expression of parameters and v`, path, value: power,
    onEdit: (t) => {
      text = t;
      onPower(t, true);
    },
  });
  field.element.dataset.endField = 'power';
  const button = rowButton(field.element, {
    text: '#', hook: 'power-number', title: '',
    onClick: () => {
      const value = powerValue(scene, text);
      if (value === null) return;
      onPower(value, false);
      onKind();
    },
  });
  // After each solve (the parameter's slider may have moved, the text changed).
  const sync = () => {
    const value = powerValue(scene, text);
    button.disabled = value === null;
    button.title = value === null
      ? 'only a number or a parameter\'s name can become a slider'
      : `replace by its current value (${value}) with a slider of its own`;
  };
  sync();
  return { field, sync };
}
