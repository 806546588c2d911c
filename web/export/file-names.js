// Names of exported files, from the scene's id: the example's id while an example is open,
// else a slug of the scene's title, else "scene"; a PNG above 1× says its scale
// ("you2004-fig2a@2x.png"). Only [a-z0-9-] (and the example id's own [A-Za-z0-9_.-]) reach
// a file name, so no title can name a path or a hidden file.
const MAX_BASE = 64;

/** "Cône & plane: b = 1" -> "cone-plane-b-1"; "" when nothing usable is left. */
export function slugOf(text) {
  return String(text)
    .normalize('NFKD')
    .replace(/[\u0300-\u036f]/g, '') // accents, split off by NFKD
    .toLowerCase()
    .replace(/[^a-z0-9]+/g, '-')
    .slice(0, MAX_BASE)
    .replace(/^-+|-+$/g, '');
}

/** { exampleId, title } -> the base of every exported file's name. */
export function exportBaseName({ exampleId, title }) {
  if (typeof exampleId === 'string') {
    const id = exampleId.replace(/[^A-Za-z0-9_.-]+/g, '-').replace(/^[.-]+/, '').slice(0, MAX_BASE);
    if (id) return id;
  }
  if (typeof title === 'string') {
    const slug = slugOf(title);
    if (slug) return slug;
  }
  return 'scene';
}

/** The PNG's name at `scale` (1, 2, 4, or a clamped fraction: rounded to 2 decimals). */
export function pngFileName(base, scale) {
  if (scale === 1) return `${base}.png`;
  return `${base}@${Number(scale.toFixed(2))}x.png`;
}
