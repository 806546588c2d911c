// The page's own shortcuts (web/ui/help-overlay.js lists them): they act only when the
// focus is not in a text field, so typing an expression never fits the view or opens help.
// Undo and redo live with the history (web/features/history.js); orbit and zoom keys with
// the view (web/viewer/camera-rig.js).

/** Whether key presses at `target` belong to a field that takes text. */
export function isTextField(target) {
  if (!target || !(target instanceof Element)) return false;
  if (target.isContentEditable) return true;
  if (target.tagName === 'TEXTAREA' || target.tagName === 'SELECT') return true;
  if (target.tagName !== 'INPUT') return false;
  return !['checkbox', 'radio', 'button', 'range', 'color', 'file', 'submit', 'reset'].includes(target.type);
}

/** { fit(), help: { toggle, isOpen, close }, layout } */
export function installShortcuts({ fit, help, layout }) {
  // Capture: lil-gui stops keydown from leaving its panel, and Esc must close the panel's
  // sheet from inside it too.
  window.addEventListener('keydown', (ev) => {
    if (ev.defaultPrevented || ev.ctrlKey || ev.metaKey || ev.altKey) return;
    if (ev.key === 'Escape') {
      if (!help.isOpen() && layout.closeDrawers()) ev.preventDefault();
      return; // an open <dialog> closes itself on Escape
    }
    if (isTextField(ev.target)) return;
    if (ev.key === '?') {
      ev.preventDefault();
      help.toggle();
    } else if ((ev.key === 'f' || ev.key === 'F') && !help.isOpen()) {
      ev.preventDefault();
      fit();
    }
  }, true);
}
