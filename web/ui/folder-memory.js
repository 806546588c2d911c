// Which lil-gui folders are open, by their title path ("Bézier “hat”/Edit the initial net"),
// so that folders rebuilt for the same scene (after an undo or redo) open and close as the
// user left them instead of as a freshly opened scene shows them.

function pathOf(folder) {
  const titles = [];
  for (let f = folder; f && f.parent; f = f.parent) titles.unshift(f._title);
  return titles.join('/');
}

const isClosed = (folder) => folder.domElement.classList.contains('closed');

/** Note every folder's state under `gui`; returns reopen(gui), which puts it back on same-path folders. */
export function rememberFolders(gui) {
  const closed = new Map(gui.foldersRecursive().map((f) => [pathOf(f), isClosed(f)]));
  return function reopen(root) {
    for (const f of root.foldersRecursive()) {
      const was = closed.get(pathOf(f));
      if (was !== undefined && was !== isClosed(f)) f.open(!was);
    }
  };
}
