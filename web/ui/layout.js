// Which parts of the page are open, as classes on <body> that web/style.css lays out.
// Wide screens (more than COMPACT px) dock the gallery left and the panel right; the
// gallery can be collapsed (body.gallery-closed). Compact screens (phones, portrait
// tablets) give the whole window to the 3D view: the gallery is a drawer from the left
// (body.gallery-open) and the panel a sheet from the bottom (body.panel-open), each
// opened by a toolbar button and closed by it, by Escape or by its own close control.

export const COMPACT = '(max-width: 900px)'; // web/style.css uses the same width

/** onChange() after any change of what is open (the view resizes itself). Returns the layout. */
export function createLayout(onChange = () => {}) {
  const body = document.body;
  const compact = window.matchMedia(COMPACT);
  const listeners = [];

  function set(cls, on) {
    body.classList.toggle(cls, on);
    for (const f of listeners) f();
    onChange();
  }

  const layout = {
    isCompact: () => compact.matches,
    galleryShown: () => (compact.matches ? body.classList.contains('gallery-open') : !body.classList.contains('gallery-closed')),
    panelShown: () => (compact.matches ? body.classList.contains('panel-open') : true),

    showGallery(on) {
      if (compact.matches) {
        if (on) body.classList.remove('panel-open'); // one drawer at a time on a small screen
        set('gallery-open', on);
      } else {
        set('gallery-closed', !on);
      }
    },
    toggleGallery() {
      layout.showGallery(!layout.galleryShown());
    },
    showPanel(on) {
      if (!compact.matches) return;
      if (on) body.classList.remove('gallery-open');
      set('panel-open', on);
    },
    togglePanel() {
      layout.showPanel(!layout.panelShown());
    },
    /** Close what covers the view on a small screen; returns whether anything was open. */
    closeDrawers() {
      if (!compact.matches) return false;
      const open = body.classList.contains('gallery-open') || body.classList.contains('panel-open');
      body.classList.remove('gallery-open', 'panel-open');
      if (open) {
        for (const f of listeners) f();
        onChange();
      }
      return open;
    },
    /** f() after each change, e.g. to update a toggle's label. */
    onChange(f) {
      listeners.push(f);
    },
  };
  // Crossing the breakpoint starts the new layout with its drawers closed.
  compact.addEventListener('change', () => {
    body.classList.remove('gallery-open', 'panel-open');
    for (const f of listeners) f();
    onChange();
  });
  return layout;
}
