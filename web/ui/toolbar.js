// The toolbar over the top of the 3D view: the page's actions (undo and redo, fit the
// view, help, and at small sizes the buttons that open the gallery and the panel).
// Buttons only, built with createElement/textContent. DOM hooks: #toolbar,
// data-action="<name>" on each button.

/** root: the empty #toolbar element. Returns { add(spec) -> button, button(action) }. */
export function createToolbar(root) {
  root.setAttribute('role', 'toolbar');
  root.setAttribute('aria-label', 'view and history');
  const buttons = new Map();
  return {
    /**
     * spec: { action, label (short text or a symbol), title (says what it does, with its
     * shortcut), onClick(), group? } — buttons of one group sit together, groups in the
     * order they first appear.
     */
    add({ action, label, title, onClick, group = 'main' }) {
      let box = root.querySelector(`[data-group="${group}"]`);
      if (!box) {
        box = document.createElement('div');
        box.className = 'toolbar-group';
        box.dataset.group = group;
        root.append(box);
      }
      const b = document.createElement('button');
      b.type = 'button';
      b.className = 'toolbar-button';
      b.dataset.action = action;
      b.textContent = label;
      b.title = title;
      b.setAttribute('aria-label', title);
      b.addEventListener('click', () => onClick());
      box.append(b);
      buttons.set(action, b);
      return b;
    },
    button(action) {
      return buttons.get(action) || null;
    },
  };
}
