// One expression text field (lil-gui string controller) with room for the solver's
// message right under it. The message is set with textContent: it quotes what the
// user typed, which may look like markup.
// DOM hooks: data-expr="<solver path>" on the controller, .expr-error for the message.
import { escapeHtml } from './html-text.js';

/**
 * Add a field to `folder`. spec: { label, title, path, value, onEdit(text) }.
 * Returns { path, element (the controller's root), showError(message | null), destroy() }.
 */
export function buildExpressionField(folder, { label, title, path, value, onEdit }) {
  const model = { text: value };
  const ctrl = folder.add(model, 'text').name(escapeHtml(label)).onChange((text) => onEdit(String(text)));
  const root = ctrl.domElement;
  root.classList.add('expr');
  root.dataset.expr = path;
  root.title = title ? `${title} (${path})` : path;
  const input = root.querySelector('input');
  input.spellcheck = false;
  input.setAttribute('autocomplete', 'off');

  const message = document.createElement('div');
  message.className = 'expr-error';
  message.setAttribute('role', 'alert');
  message.hidden = true;
  root.append(message);

  return {
    path,
    element: root,
    showError(text) {
      const on = typeof text === 'string' && text !== '';
      message.hidden = !on;
      message.textContent = on ? text : '';
      root.classList.toggle('invalid', on);
      input.setAttribute('aria-invalid', String(on));
    },
    destroy() {
      ctrl.destroy();
    },
  };
}

/**
 * The field a solver message is about: the one whose path it names ("<path>: …"),
 * else `fallback` (the field edited last) when the message names no field at all.
 */
export function fieldForMessage(fields, message, fallback) {
  let best = null;
  for (const f of fields) {
    const at = message.indexOf(`${f.path}:`);
    // A longer path that matches is the more precise one.
    if (at >= 0 && (!best || f.path.length > best.path.length)) best = f;
  }
  if (best) return best;
  return /patches\[\d+\]/.test(message) ? null : fallback || null;
}
