// Dropping a file anywhere on the page: while files are dragged over it the body has the
// class "file-drop" (a subtle highlight, style.css); a drop hands the first file over.
// Drags that carry no file (text, a link) are left to the browser.
const CLASS = 'file-drop';

const carriesFiles = (e) => Boolean(e.dataTransfer) && Array.from(e.dataTransfer.types || []).includes('Files');

/** onFile(file) is called with the dropped file. Returns { dispose() }. */
export function installFileDrop(onFile, target = window) {
  let depth = 0; // dragenter/dragleave pairs: leaving a child element is not leaving the page
  const body = document.body;
  const reset = () => {
    depth = 0;
    body.classList.remove(CLASS);
  };
  const handlers = {
    dragenter(e) {
      if (!carriesFiles(e)) return;
      e.preventDefault();
      depth++;
      body.classList.add(CLASS);
    },
    dragover(e) {
      if (!carriesFiles(e)) return;
      e.preventDefault(); // without it the browser opens the file instead of dropping it here
      e.dataTransfer.dropEffect = 'copy';
    },
    dragleave(e) {
      if (!carriesFiles(e)) return;
      depth = Math.max(0, depth - 1);
      if (depth === 0) body.classList.remove(CLASS);
    },
    drop(e) {
      if (!carriesFiles(e)) return;
      e.preventDefault();
      reset();
      const file = e.dataTransfer.files[0];
      if (file) onFile(file);
    },
  };
  for (const [type, fn] of Object.entries(handlers)) target.addEventListener(type, fn);
  return {
    dispose() {
      for (const [type, fn] of Object.entries(handlers)) target.removeEventListener(type, fn);
      reset();
    },
  };
}
