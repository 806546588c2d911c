// The help overlay (the ? key or the toolbar's ? button): the page's shortcuts and gestures,
// and links to the docs. A <dialog>, so Escape and the close button dismiss it and the focus
// returns where it was. Static text only, built with createElement/textContent.
// DOM hooks: #help, data-help="close".

const SHORTCUTS = [
  ['?', 'show or hide this help'],
  ['F', 'fit the view to every patch'],
  ['Ctrl+Z  (⌘Z)', 'undo the last change to the scene'],
  ['Ctrl+Shift+Z, Ctrl+Y  (⇧⌘Z)', 'redo'],
  ['Esc', 'close this help, or the examples or controls drawer'],
  ['Tab', 'move between controls; the 3D view takes the focus too'],
  ['← → ↑ ↓', 'in the 3D view: orbit; on a slider: change its value (Shift: ×10)'],
  ['+  −', 'in the 3D view: zoom in and out'],
  ['Page Up/Down, Home, End', 'on a slider: big steps, its ends'],
];
const GESTURES = [
  ['drag', 'orbit'],
  ['right-drag, or Shift+drag', 'pan'],
  ['wheel, or pinch', 'zoom (limited to the scene\'s size)'],
  ['double-click on a surface', 'orbit about that point'],
  ['drop a scene file on the page', 'open it'],
];
const DOCS = [
  ['/docs/page.md', 'Using the page'],
  ['/docs/scene-format-v2.md', 'Scene files'],
  ['/docs/analysis.md', 'Analysis: curvature, zebra, join certificate'],
];

function el(tag, text, className) {
  const node = document.createElement(tag);
  if (className) node.className = className;
  if (text !== undefined) node.textContent = text;
  return node;
}

function table(caption, rows) {
  const t = el('table', undefined, 'help-table');
  t.append(el('caption', caption));
  for (const [key, what] of rows) {
    const tr = el('tr');
    tr.append(el('th', key), el('td', what));
    t.append(tr);
  }
  return t;
}

/** Build the dialog into <body>. Returns { toggle(), open(), close(), isOpen() }. */
export function createHelpOverlay() {
  const dialog = el('dialog');
  dialog.id = 'help';
  dialog.setAttribute('aria-labelledby', 'help-title');
  const head = el('div', undefined, 'help-head');
  const title = el('h2', 'pdesurf: keys and gestures');
  title.id = 'help-title';
  const close = el('button', '×', 'help-close');
  close.type = 'button';
  close.title = 'close (Esc)';
  close.dataset.help = 'close';
  close.addEventListener('click', () => dialog.close());
  head.append(title, close);
  const docs = el('p', 'Docs: ', 'help-docs');
  DOCS.forEach(([href, text], k) => {
    const a = el('a', text);
    a.href = href;
    a.target = '_blank';
    a.rel = 'noopener';
    docs.append(a);
    if (k < DOCS.length - 1) docs.append(' · ');
  });
  dialog.append(head, table('Keys', SHORTCUTS), table('Mouse and touch', GESTURES), docs);
  // A click on the backdrop (outside the box) closes it too.
  dialog.addEventListener('click', (ev) => {
    if (ev.target === dialog) dialog.close();
  });
  document.body.append(dialog);
  const api = {
    isOpen: () => dialog.open,
    open() {
      if (!dialog.open) dialog.showModal();
    },
    close() {
      dialog.close();
    },
    toggle() {
      if (dialog.open) dialog.close();
      else dialog.showModal();
    },
  };
  return api;
}
