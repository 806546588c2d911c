// Wiring of the "File" folder: exports (scene JSON; OBJ, STL, GLB, 3MF of the watertight mesh
// and STEP, IGES, 3dm fitted, both made in the solver's worker; PNG; web/export/) and
// opening a scene file, or a CAD file's surfaces (.3dm, STEP, IGES: web/cad/), by the picker or by
// dropping it on the page (web/import/). A file
// that cannot be read, or whose scene does not solve, leaves the page as it was: the drawn
// surfaces, the panel, the example id and the URL hash. For the second case the scene shown
// before is remembered and shown again (with its camera) when the file's first solve fails.
import { buildFileFolder } from '../ui/file-controls.js';
import { createFilePicker } from '../import/file-picker.js';
import { installFileDrop } from '../import/file-drop.js';
import { downloadFile } from '../export/download.js';
import { exportBaseName, pngFileName } from '../export/file-names.js';
import { messageOf } from '../state/document.js';

// What runs only once a file is opened or exported loads then (the cold start stays as it was).
const meshExport = () => import('../export/mesh-export.js');
const pngExport = () => import('../export/png-export.js');
const sceneExport = () => import('../export/scene-export.js');
const cadExport = () => import('../export/cad-export.js');
const CAD_LABELS = { step: 'STEP', iges: 'IGES', '3dm': '3dm' };
const sceneFile = () => import('../import/scene-file.js');

const nextPaint = () => new Promise((resolve) => requestAnimationFrame(() => setTimeout(resolve, 0)));
const sizeText = (bytes) => (bytes < 1024 ? `${bytes} bytes` : bytes < 1 << 20 ? `${(bytes / 1024).toFixed(0)} KiB` : `${(bytes / (1 << 20)).toFixed(1)} MiB`);

/**
 * The context's { panel, viewer, state, status, hooks, solver (solver/solver-client.js: CAD
 *   exports run in its worker), session (showScene(scene, opts) -> token; setNotice(text),
 *   shown instead of the next solve's summary), titleEl (the title line) }.
 * Returns { solved(job) -> true for the first good solve of an opened file (its scene is
 * then linked in the hash like an edit), failed(err, job) -> true when the failure was an
 * opened file's (handled here) }.
 */
export function createFilesFeature({ panel, viewer, state, status, hooks, solver, session, titleEl }) {
  const showScene = (scene, opts) => session.showScene(scene, opts);
  const setNotice = (text) => session.setNotice(text);
  const currentTitle = () => titleEl.textContent;
  let pending = null; // { token, name, previous }: an opened file's scene waiting for its first solve
  let busy = false; // one export at a time

  const baseName = () => exportBaseName({ exampleId: state.exampleId, title: state.scene?.title });
  const surfaces = () => viewer.sceneGraph().surfaces;

  function refuse(name, err) {
    const msg = `cannot open ${name}: ${messageOf(err)}`;
    hooks.notice = msg;
    hooks.lastFile = { action: 'open', name, error: msg };
    status.error(msg);
  }

  // A CAD file's faces as a scene (docs/cad-import.md): .3dm through rhino3dm, STEP through
  // Open CASCADE, IGES's B-spline surfaces by read-iges.js; each in a worker of its own started
  // on first use.
  async function readCadFile(file, name) {
    const ext = name.toLowerCase().split('.').pop();
    const { checkFileSize } = await import('../cad/cad-scene.js');
    checkFileSize(file.size);
    if (ext === 'igs' || ext === 'iges') {
      status.info(`reading ${name}…`);
      return { scene: await (await import('../cad/import-iges.js')).importIges(await file.arrayBuffer(), name), title: null, download: null };
    }
    const step = ext === 'step' || ext === 'stp';
    status.info(`reading ${name} (${step ? 'Open CASCADE, 23 MB,' : 'rhino3dm'} loads on first use)…`);
    // Open CASCADE's first download, said as it comes (at most once a percent).
    let download = null;
    const onProgress = ({ loaded, total }) => {
      download = { loaded, total };
      status.info(loaded < total ? `loading Open CASCADE to read ${name}: ${sizeText(loaded)} of ${sizeText(total)} (${Math.floor((100 * loaded) / total)} %)…`
        : `reading ${name}…`);
    };
    const scene = step ? await (await import('../cad/import-step.js')).importStep(await file.arrayBuffer(), name, { onProgress })
      : await (await import('../cad/export-3dm.js')).import3dm(await file.arrayBuffer(), name);
    return { scene, title: null, download }; // the file name is the title
  }

  async function openFile(file) {
    const name = file.name || 'the file';
    let read;
    try {
      read = /\.(3dm|step|stp|igs|iges)$/i.test(name) ? await readCadFile(file, name) : await (await sceneFile()).readSceneFile(file);
    } catch (err) {
      refuse(name, err);
      return;
    }
    // Another file still waiting for its first solve: the scene to come back to is the one before it.
    let previous = pending ? pending.previous : null;
    try {
      if (!pending && state.scene) previous = { text: state.text(), exampleId: state.exampleId, title: currentTitle(), camera: viewer.getCamera() };
    } catch {
      previous = null; // a page state that cannot be written as JSON cannot be restored either
    }
    const token = showScene(read.scene, { title: read.title ? `${read.title} (${name})` : name });
    pending = { token, name, previous };
    hooks.lastFile = { action: 'open', name, error: null, download: read.download ?? null };
  }

  // make() -> { data, name, type, note? (a warning for the status line), record? (more for
  // hooks.lastFile) }; said(text, kind): where else the outcome goes (the CAD line).
  async function exportWith(action, make, { label = action.toUpperCase(), said = () => {} } = {}) {
    if (busy) return;
    busy = true;
    const t0 = performance.now();
    try {
      // A large OBJ takes a second on the page's thread: say so before it starts.
      status.info(`exporting ${label}…`);
      await nextPaint();
      const { data, name, type, note, record } = await make();
      const bytes = downloadFile(data, name, type);
      const ms = performance.now() - t0;
      hooks.lastFile = { action, name, bytes, ms, ...record };
      const line = `saved ${name} (${sizeText(bytes)})`;
      if (note) status.warn(`${line}; ${note}`);
      else status.info(line);
    } catch (err) {
      if (err?.code === 'Cancelled') {
        const msg = `${label} export cancelled`;
        hooks.lastFile = { action, cancelled: true };
        status.info(msg);
        said(msg);
        return;
      }
      const msg = `cannot export ${label}: ${messageOf(err)}`;
      hooks.lastFile = { action, error: msg };
      status.error(msg);
      said(msg, 'error');
    } finally {
      busy = false;
    }
  }

  // format: step, iges or 3dm; toleranceText: the folder's field (blank: the default). The fit
  // reports each patch done: the folder's bar follows, and its cancel button ends the export.
  function cadFile(format, toleranceText) {
    const label = CAD_LABELS[format];
    const said = (text, kind) => fileFolder.sayCad(text, kind);
    return exportWith(format, async () => {
      if (!state.scene) throw new Error('no scene is open');
      const cad = await cadExport();
      const tolerance = cad.parseTolerance(toleranceText);
      said(`fitting ${label}…`);
      fileFolder.cadProgress(0);
      const onProgress = (done, total, patch) => {
        fileFolder.cadProgress(done / total);
        said(`fitting ${label}: ${done} of ${total} patches (${patch})`);
      };
      let file;
      try {
        file = await cad.cadFile({ solver, sceneText: state.text(), format, tolerance, base: baseName(), onProgress });
      } finally {
        fileFolder.cadProgress(null);
      }
      const summary = cad.fitSummary(format, file.fit);
      said(summary.text, summary.missed.length || summary.joinsOff ? 'warn' : null);
      const note = summary.missed.length ? `normals target not reached on ${summary.missed.join(', ')}`
        : summary.joinsOff ? `${summary.joinsOff} join${summary.joinsOff === 1 ? '' : 's'} between faces off target` : null;
      return { ...file, note, record: cad.fitRecord(file.fit) };
    }, { label, said });
  }

  // The model's watertight mesh from the worker (modelMesh) on the page's grid, then the file.
  const MESH_FILES = {
    obj: { type: 'model/obj', write: (m, model, colours) => m.exportObj(model, colours) },
    stl: { type: 'model/stl', write: (m, model, colours) => m.exportStl(model, colours) },
    glb: { type: 'model/gltf-binary', write: (m, model, colours) => m.exportGlb(model, colours, baseName()) },
    '3mf': { type: 'model/3mf', write: (m, model) => m.export3mf(model, state.scene?.title || baseName()) },
  };
  function meshFile(format) {
    const { type, write } = MESH_FILES[format];
    return exportWith(format, async () => {
      if (!state.scene || !surfaces().children.length) throw new Error('no surface is drawn yet');
      const [m, model] = await Promise.all([meshExport(), solver.modelMesh(state.text(), { nu: state.grid.nu, nv: state.grid.nv })]);
      // A printer needs closed bodies: 3MF says which are not (open surfaces are the rule elsewhere).
      const open = model.bodies.filter((b) => !b.closed).length;
      const note = format === '3mf' && open ? `${open} of ${model.bodies.length} bod${model.bodies.length === 1 ? 'y is' : 'ies are'} open (not printable)` : null;
      const bodies = model.bodies.map((b) => ({ closed: b.closed, volume: b.volume }));
      return { data: await write(m, model, m.drawnColours(surfaces())), name: `${baseName()}.${format}`, type, note, record: { bodies } };
    });
  }

  const picker = createFilePicker(openFile);
  installFileDrop(openFile);
  const fileFolder = buildFileFolder(panel.gui, {
    open: () => picker.open(),
    json: () => exportWith('json', async () => {
      if (!state.scene) throw new Error('no scene is open');
      const text = (await sceneExport()).sceneFileText(state.scene);
      return { data: text, name: `${baseName()}.json`, type: 'application/json' };
    }),
    mesh: meshFile,
    cad: cadFile,
    cancelCad: () => solver.cancelExport(),
    png: ({ scale, transparent }) => exportWith('png', async () => {
      const { scene } = viewer.sceneGraph();
      const { renderPng } = await pngExport();
      const png = await renderPng({ renderer: viewer.renderer, scene, camera: viewer.camera }, { scale, transparent });
      viewer.render();
      const note = png.clamped ? `reduced to ${png.width}×${png.height} (${png.scale.toFixed(2)}×): ${png.limit}` : null;
      return { data: png.blob, name: pngFileName(baseName(), png.scale), type: 'image/png', note };
    }),
  });
  panel.keepAfterShare(fileFolder.folder);

  return {
    solved(job) {
      if (!pending) return false;
      const mine = job.token === pending.token;
      if (mine || job.token > pending.token) pending = null;
      return mine;
    },

    failed(err, job) {
      if (!pending || job.token !== pending.token) return false;
      const { name, previous } = pending;
      pending = null;
      const msg = `cannot open ${name}: ${messageOf(err)}`;
      hooks.lastFile = { action: 'open', name, error: msg };
      if (!previous) {
        hooks.notice = msg;
        status.error(msg);
        return true;
      }
      // Shown instead of the summary of the solve that brings the previous scene back.
      setNotice(msg);
      showScene(JSON.parse(previous.text), { exampleId: previous.exampleId, title: previous.title, camera: previous.camera });
      return true;
    },
  };
}
