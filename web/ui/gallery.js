// The example gallery: every entry of examples/index.json, grouped by paper, one
// click each. Built with createElement/textContent only: titles, figures and
// descriptions are shown as text whatever they contain.
// DOM hooks: #gallery, data-example="<id>" on each entry's button.

function el(tag, className, text) {
  const node = document.createElement(tag);
  if (className) node.className = className;
  if (text !== undefined) node.textContent = text;
  return node;
}

/** Catalogue entries grouped by source.paper, in catalogue order. */
export function groupByPaper(examples) {
  const groups = new Map();
  for (const e of examples) {
    const paper = (e.source && typeof e.source.paper === 'string' && e.source.paper) || 'other examples';
    if (!groups.has(paper)) groups.set(paper, []);
    groups.get(paper).push(e);
  }
  return groups;
}

/**
 * Build the gallery into `root` (an empty <aside>). onOpen(id) runs on a click; layout
 * (web/ui/layout.js) opens and closes it. Returns { setActive(id | null, description?) }.
 */
export function createGallery(root, examples, onOpen, layout) {
  root.id = 'gallery';
  const head = el('div', 'gallery-head');
  head.append(el('h1', 'gallery-heading', 'Examples'));
  const toggle = el('button', 'gallery-toggle', '‹');
  toggle.type = 'button';
  toggle.title = 'hide the examples';
  toggle.setAttribute('aria-expanded', 'true');
  head.append(toggle);

  const list = el('nav', 'gallery-list');
  list.setAttribute('aria-label', 'examples by paper');
  const items = new Map(); // id -> { li, button }
  for (const [paper, entries] of groupByPaper(examples)) {
    const section = el('section', 'gallery-group');
    section.append(el('h2', 'gallery-paper', paper));
    const ul = el('ul');
    for (const e of entries) {
      const li = el('li');
      const button = el('button', 'gallery-item');
      button.type = 'button';
      button.dataset.example = e.id;
      const figure = e.source && typeof e.source.figure === 'string' ? e.source.figure : '';
      if (figure) button.append(el('span', 'gallery-figure', figure));
      button.append(el('span', 'gallery-caption', e.title));
      button.addEventListener('click', () => onOpen(e.id));
      li.append(button);
      ul.append(li);
      items.set(e.id, { li, button });
    }
    section.append(ul);
    list.append(section);
  }
  root.append(head, list);

  // Collapsing gives the whole window to the view; on a small screen the gallery is a
  // drawer over the view that closes after a pick.
  function showToggle() {
    const shown = layout.galleryShown();
    toggle.textContent = shown ? '‹' : '›';
    toggle.title = shown ? 'hide the examples' : 'show the examples';
    toggle.setAttribute('aria-expanded', String(shown));
  }
  layout.onChange(showToggle);
  showToggle();
  toggle.addEventListener('click', () => layout.toggleGallery());
  list.addEventListener('click', (ev) => {
    if (layout.isCompact() && ev.target.closest('[data-example]')) layout.showGallery(false);
  });

  let active = null;
  const description = el('p', 'gallery-description');

  return {
    /** Mark the open example (null: a scene from a link) and show its description. */
    setActive(id, text) {
      if (active) {
        active.button.classList.remove('active');
        active.button.removeAttribute('aria-current');
      }
      description.remove();
      active = items.get(id) || null;
      if (!active) return;
      active.button.classList.add('active');
      active.button.setAttribute('aria-current', 'true');
      if (typeof text === 'string' && text) {
        description.textContent = text;
        active.li.append(description);
      }
      active.button.scrollIntoView({ block: 'nearest' });
    },
  };
}
