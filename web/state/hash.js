// The URL hash says what the page opens: "#s=…" a shared page state (web/link/),
// "#example=<id>" an example, nothing the default example.

// The hash that matches what the page shows (written by it, or opened from it): a
// hashchange to it is the page's own doing and must not re-open the state.
let shown = null;

/** { kind: 'state', text } | { kind: 'example', id } | { kind: 'none' } */
export function readHash(hash = location.hash) {
  const body = hash.replace(/^#/, '');
  // A state link is checked first and handed over whole: the link codec parses it
  // (URLSearchParams would turn a '+' a mail client left in it into a space).
  if (body.split('&').some((part) => part.startsWith('s='))) return { kind: 'state', text: body };
  const id = new URLSearchParams(body).get('example');
  return id ? { kind: 'example', id } : { kind: 'none' };
}

/** The example id named in the hash, or null. */
export function exampleIdFromHash(hash = location.hash) {
  const h = readHash(hash);
  return h.kind === 'example' ? h.id : null;
}

/** The page now shows what the current hash names. */
export function markHashShown() {
  shown = location.hash;
}

/** True when the current hash is the one the page shows (nothing new to open). */
export function hashIsShown() {
  return location.hash === shown;
}

/** Write the id into the hash without adding a history entry or firing hashchange. */
export function writeExampleIdToHash(id) {
  history.replaceState(null, '', '#' + new URLSearchParams({ example: id }).toString());
  markHashShown();
}

/** Empty the hash, the same way: the page shows what no link can hold (a reload opens the default). */
export function clearHash() {
  history.replaceState(null, '', location.pathname + location.search);
  markHashShown();
}

/** Write a shared-state link ("s=1.…") into the hash, the same way. */
export function writeLinkToHash(link) {
  history.replaceState(null, '', '#' + link);
  markHashShown();
}
