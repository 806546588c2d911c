// The "File" folder: open a scene file, and export the scene (JSON), the model as watertight
// meshes (OBJ, STL, GLB, 3MF) or as certified B-spline faces for CAD (STEP, IGES, 3dm, at a tolerance
// typed here; empty: the core's default) and the view (PNG at 1×, 2× or 4× the canvas,
// optionally transparent). Names go through escapeHtml (lil-gui writes them as markup); the
// CAD line under the buttons is written with textContent only; while a CAD export runs, a
// progress bar (patches fitted of all) and a cancel button stand under it. DOM hooks: data-file="open" |
// "json" | "obj" | "stl" | "glb" | "3mf" | "cad-tolerance" | "step" | "iges" | "3dm" | "cad-message" |
// "png" | "png-scale" | "png-transparent" | "cad-progress" | "cad-cancel".
import { escapeHtml } from './html-text.js';

export const PNG_SCALES = { '1×': 1, '2×': 2, '4×': 4 };

/**
 * handlers: { open(), json(), mesh(format) with format 'obj' | 'stl' | 'glb' | '3mf', cad(format, toleranceText) with format
 * 'step' | 'iges' | '3dm', cancelCad(), png({ scale, transparent }) }.
 * Returns { folder (its element), sayCad(text, kind) (the CAD line: kind null, 'warn' or 'error'),
 * cadProgress(fraction) (0..1 shows the bar and the cancel button; null hides them) }.
 */
export function buildFileFolder(gui, handlers) {
  const folder = gui.addFolder('File');
  folder.domElement.dataset.folder = 'file';
  const png = { scale: 1, transparent: false };
  const cad = { tolerance: '' };
  const actions = {
    open: () => handlers.open(),
    json: () => handlers.json(),
    png: () => handlers.png({ ...png }),
  };
  const button = (key, label, title) => {
    const c = folder.add(actions, key).name(escapeHtml(label));
    c.domElement.dataset.file = key;
    c.domElement.title = title;
    return c;
  };
  button('open', 'open scene or CAD file…', "open a scene (.json), or the surfaces of a STEP, IGES or Rhino .3dm file, from this computer; or drop the file on the page");
  button('json', 'export scene JSON', 'the scene as a file the page and the pdesurf CLI open');
  folder.$children.append(buttonRow('export mesh', MESH_BUTTONS, (format) => handlers.mesh(format)));
  const tol = folder.add(cad, 'tolerance').name(escapeHtml('CAD tolerance'));
  tol.domElement.dataset.file = 'cad-tolerance';
  tol.domElement.title = 'the largest distance allowed between a patch and its B-spline face, in scene units (e.g. 1e-4); empty: 1e-6 of the scene\'s diagonal';
  tol.$input.placeholder = 'default';
  tol.$input.inputMode = 'decimal';
  tol.$input.spellcheck = false;
  folder.$children.append(buttonRow('export CAD', CAD_BUTTONS, (format) => handlers.cad(format, cad.tolerance)));
  // What the last CAD export achieved, or why it failed: text only (patch names come from links).
  const message = document.createElement('div');
  message.className = 'cad-message';
  message.dataset.file = 'cad-message';
  message.setAttribute('role', 'status');
  message.hidden = true;
  folder.$children.append(message);
  const progressRow = document.createElement('div');
  progressRow.className = 'cad-progress';
  progressRow.dataset.file = 'cad-progress';
  progressRow.hidden = true;
  const bar = document.createElement('progress');
  bar.max = 1;
  bar.value = 0;
  bar.setAttribute('aria-label', 'CAD export progress');
  const cancel = document.createElement('button');
  cancel.type = 'button';
  cancel.dataset.file = 'cad-cancel';
  cancel.textContent = 'cancel';
  cancel.title = 'stop this CAD export (the solver restarts; nothing is written)';
  cancel.addEventListener('click', () => handlers.cancelCad());
  progressRow.append(bar, cancel);
  folder.$children.append(progressRow);
  const labels = Object.fromEntries(Object.entries(PNG_SCALES).map(([k, v]) => [escapeHtml(k), v]));
  folder.add(png, 'scale', labels).name(escapeHtml('PNG size')).domElement.dataset.file = 'png-scale';
  folder.add(png, 'transparent').name(escapeHtml('PNG transparent')).domElement.dataset.file = 'png-transparent';
  button('png', 'export PNG', 'the view as a PNG image, at the chosen multiple of the canvas size');
  folder.close();
  return {
    folder: folder.domElement,
    sayCad(text, kind = null) {
      message.textContent = text;
      message.hidden = !text;
      message.classList.toggle('warn', kind === 'warn');
      message.classList.toggle('error', kind === 'error');
    },
    cadProgress(fraction) {
      progressRow.hidden = fraction === null;
      if (fraction !== null) bar.value = Math.min(1, Math.max(0, fraction));
    },
  };
}

// The model's mesh: the patches share the vertices of their joins, so a closed model is one
// watertight body (printable); one object per body.
const MESH_BUTTONS = [
  ['obj', 'OBJ', 'the model as a Wavefront OBJ mesh, one object per body, watertight along every join'],
  ['stl', 'STL', 'the model as a binary STL mesh, watertight along every join'],
  ['glb', 'GLB', 'the model as glTF 2.0 (binary): a mesh per body, a primitive per patch'],
  ['3mf', '3MF', 'the model as a 3MF file for printing, one object per body'],
];

const CAD_BUTTONS = [
  ['step', 'STEP', 'every patch as a certified B-spline face in a STEP file (AP214)'],
  ['iges', 'IGES', 'every patch as a certified B-spline surface in an IGES file (type 128)'],
  ['3dm', '3dm', 'every patch as a certified NURBS surface in a Rhino .3dm file (loads rhino3dm, 0.8 MB, on first use)'],
];

// "export CAD [STEP] [IGES] [3dm]", "export mesh [OBJ] …": one row in lil-gui's own classes (a
// row per format took the folder past the sheet of a phone with touch-sized rows). Each button
// is "export FORMAT" to assistive technology; built with textContent only.
function buttonRow(text, buttons, onExport) {
  const row = document.createElement('div');
  row.className = 'controller cad-export';
  const name = document.createElement('div');
  name.className = 'name';
  name.textContent = text;
  const widget = document.createElement('div');
  widget.className = 'widget';
  for (const [key, label, title] of buttons) {
    const slot = document.createElement('span');
    slot.dataset.file = key;
    const b = document.createElement('button');
    b.type = 'button';
    b.textContent = label;
    b.title = title;
    b.setAttribute('aria-label', `export ${label}`);
    b.addEventListener('click', () => onExport(key));
    slot.append(b);
    widget.append(slot);
  }
  row.append(name, widget);
  return row;
}
