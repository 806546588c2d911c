// The "File" folder: open a scene file, and export the scene (JSON), the patches (OBJ, STL,
// GLB) and the view (PNG at 1×, 2× or 4× the canvas, optionally transparent). Names go
// through escapeHtml (lil-gui writes them as markup). DOM hooks: data-file="open" | "json" |
// "obj" | "stl" | "glb" | "png" | "png-scale" | "png-transparent".
import { escapeHtml } from './html-text.js';

export const PNG_SCALES = { '1×': 1, '2×': 2, '4×': 4 };

/**
 * handlers: { open(), json(), obj(), stl(), glb(), png({ scale, transparent }) }.
 * Returns { folder (its element) }.
 */
export function buildFileFolder(gui, handlers) {
  const folder = gui.addFolder('File');
  folder.domElement.dataset.folder = 'file';
  const png = { scale: 1, transparent: false };
  const actions = {
    open: () => handlers.open(),
    json: () => handlers.json(),
    obj: () => handlers.obj(),
    stl: () => handlers.stl(),
    glb: () => handlers.glb(),
    png: () => handlers.png({ ...png }),
  };
  const button = (key, label, title) => {
    const c = folder.add(actions, key).name(escapeHtml(label));
    c.domElement.dataset.file = key;
    c.domElement.title = title;
    return c;
  };
  button('open', 'open scene file…', 'open a scene (.json) from this computer; or drop the file on the page');
  button('json', 'export scene JSON', 'the scene as a file the page and the pdesurf CLI open');
  button('obj', 'export OBJ', 'the patches as a Wavefront OBJ mesh (one object per patch)');
  button('stl', 'export STL', 'the patches as a binary STL mesh');
  button('glb', 'export GLB', 'the patches as glTF 2.0 (binary), one node per patch');
  const labels = Object.fromEntries(Object.entries(PNG_SCALES).map(([k, v]) => [escapeHtml(k), v]));
  folder.add(png, 'scale', labels).name(escapeHtml('PNG size')).domElement.dataset.file = 'png-scale';
  folder.add(png, 'transparent').name(escapeHtml('PNG transparent')).domElement.dataset.file = 'png-transparent';
  button('png', 'export PNG', 'the view as a PNG image, at the chosen multiple of the canvas size');
  folder.close();
  return { folder: folder.domElement };
}
