// The URL hash holds the open example (#example=<id>) so a link reopens it.

/** The example id named in the hash, or null. */
export function exampleIdFromHash(hash = location.hash) {
  const params = new URLSearchParams(hash.replace(/^#/, ''));
  const id = params.get('example');
  return id ? id : null;
}

/** Write the id into the hash without adding a history entry or firing hashchange. */
export function writeExampleIdToHash(id) {
  const params = new URLSearchParams(location.hash.replace(/^#/, ''));
  params.set('example', id);
  history.replaceState(null, '', '#' + params.toString());
}
