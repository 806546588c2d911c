// The control panel (three's bundled lil-gui): sharing, files and grid resolution at the
// top, then the per-scene folders (parameters, blends' operators, blends' ends by
// reference, bezier patches, version-2 function fields), then analysis and joins.
// Scene folders are rebuilt whenever another scene opens; the gallery is elsewhere.
import GUI from 'three/addons/libs/lil-gui.module.min.js';
import { buildParameterFolder } from './parameter-controls.js';
import { buildOperatorFolders } from './operator-controls.js';
import { buildExpressionFolders } from './expression-folders.js';
import { buildEndFolders } from './end-controls.js';
import { buildShareFolder } from './share-controls.js';
import { buildBezierFolders } from './bezier-controls.js';
import { hasExpressions } from '../state/expression-edit.js';
import { rememberFolders } from './folder-memory.js';

const GRID_MIN = 4;
const GRID_MAX = 256;

/**
 * grid: {nu, nv} (shown, never written: onGridChange({ nu, nv }) asks for a change); onShare();
 * parameterHandlers: { onChange(name, value), onAdd(name, value) -> bool, onRemove(name) };
 * operatorHandlers: see buildOperatorFolders; bezierHandlers: see buildBezierFolders;
 * endHandlers: see buildEndFolders; onExpression(patch, field, text).
 */
export function createPanel({ grid, onGridChange, onShare, parameterHandlers, operatorHandlers, bezierHandlers, endHandlers, onExpression }) {
  const gui = new GUI({ title: 'pdesurf', width: 340 });
  gui.domElement.id = 'panel';

  const share = buildShareFolder(gui, onShare);
  const gridFolder = gui.addFolder('Grid');
  // A draft of the grid: a move reports the new grid and the edit writes it (refreshGrid shows the page's).
  const gridDraft = { nu: grid.nu, nv: grid.nv };
  const gridCtrls = ['nu', 'nv'].map((key) => {
    const c = gridFolder.add(gridDraft, key, GRID_MIN, GRID_MAX, 1).onChange(() => onGridChange({ nu: gridDraft.nu, nv: gridDraft.nv }));
    c.domElement.dataset.grid = key;
    return c;
  });
  gridFolder.close();

  let scene = null;
  let paramFolder = null;
  let operators = null;
  let bezier = null;
  let expressions = null;
  let ends = null;
  let lastSolved = []; // the patches of the last good solve (folders rebuilt between solves use them)
  let reopen = null; // after an undo or redo: the folders' open state, put back once they are rebuilt
  // Scene folders are appended as they are built; the top folders (share, those of
  // keepAfterShare, grid) stay first, the fixed folders (analysis and joins, see keepAtEnd) last.
  const top = [share.folder, gridFolder.domElement];
  const fixed = [];
  const fixedToEnd = () => {
    for (const el of [...top].reverse()) gui.$children.prepend(el);
    for (const el of fixed) gui.$children.appendChild(el);
  };

  // Build new folders where `old`'s were (appended at the end when there were none).
  function replaceFolders(old, build) {
    const anchor = old ? old.elements()[0] : null;
    const next = build();
    if (anchor && next) for (const el of next.elements()) gui.$children.insertBefore(el, anchor);
    old?.destroy();
    return next;
  }
  const buildEnds = () => (endHandlers ? buildEndFolders(gui, scene, lastSolved, endHandlers) : null);
  const buildExpressions = () => (hasExpressions(scene) ? buildExpressionFolders(gui, scene, lastSolved, onExpression) : null);

  function buildParameters() {
    const old = paramFolder;
    paramFolder = buildParameterFolder(gui, scene, parameterHandlers);
    // A rebuild (parameter added or removed) keeps the folder where it was, open.
    if (old) {
      gui.$children.insertBefore(paramFolder.domElement, old.domElement);
      old.destroy();
    }
  }

  return {
    gui,

    /** Folders (their elements) built outside that stay after the scene folders. */
    keepAtEnd(...elements) {
      fixed.push(...elements);
      fixedToEnd();
    },

    /**
     * Folders (their elements) built outside that stay at the top, after share and the
     * folders kept there before them (File, then Build and Model), before the grid.
     */
    keepAfterShare(...elements) {
      top.splice(top.indexOf(gridFolder.domElement), 0, ...elements);
      fixedToEnd();
    },

    /** New scene: fresh parameter sliders; operator and function folders wait for its first solve. */
    showScene(next) {
      scene = next;
      if (paramFolder) paramFolder.destroy();
      paramFolder = null;
      operators?.destroy();
      bezier?.destroy();
      expressions?.destroy();
      ends?.destroy();
      operators = bezier = expressions = ends = null;
      lastSolved = [];
      reopen = null;
      buildParameters();
      fixedToEnd();
    },

    /**
     * An undo or redo within the same scene: its parameter sliders now; the other scene
     * folders stay until the next good solve rebuilds them, open or closed as they were.
     */
    restoreScene(next) {
      scene = next;
      reopen = rememberFolders(gui);
      buildParameters();
      reopen(gui);
    },

    /** After any edit: the sliders show the scene's values (a drag may move a parameter). */
    showParameterValues() {
      paramFolder?.showValues?.();
    },

    /** Parameters were added or removed: rebuild their folder in place. */
    refreshParameters() {
      buildParameters();
    },

    /** After a successful solve: build the scene folders once per scene, else refresh them. */
    showSolved(patches) {
      lastSolved = patches;
      if (operators && !reopen) {
        operators.update(patches);
        ends?.update(patches);
        bezier.update(patches);
        expressions?.update(patches);
        return;
      }
      const carried = reopen && bezier ? bezier.ui() : null; // toggles and edited point stay through an undo
      operators?.destroy();
      bezier?.destroy();
      expressions?.destroy();
      ends?.destroy();
      operators = buildOperatorFolders(gui, patches, operatorHandlers);
      ends = buildEnds();
      bezier = buildBezierFolders(gui, scene, patches, bezierHandlers, carried);
      expressions = buildExpressions();
      reopen?.(gui);
      reopen = null;
      fixedToEnd();
    },

    /**
     * An end was attached or detached: its Ends folder and the blend's function fields
     * change shape at once (with the last solve's orders and derived texts), in place and
     * open or closed as they were.
     */
    rebuildEnds() {
      if (!operators) return; // not built yet: the first solve builds them
      const reopenNow = rememberFolders(gui);
      ends = replaceFolders(ends, buildEnds);
      expressions = replaceFolders(expressions, buildExpressions);
      reopenNow(gui);
      fixedToEnd();
    },

    /**
     * After a failed solve: the message beside the function field or in the end's folder
     * it names; returns the field's path, the end ("<patch>.<end>"), or null.
     */
    showSolveError(message) {
      const end = ends ? ends.showSolveError(message) : null;
      const field = expressions ? expressions.showSolveError(message) : null;
      return field ?? end;
    },

    /** A coordinate's order changed: its function fields follow at once. */
    setOrder(patchName, axis, order) {
      expressions?.setOrder(patchName, axis, order);
    },

    /** The page's grid changed (a link's grid, an opening, undo): show its values. */
    refreshGrid() {
      Object.assign(gridDraft, { nu: grid.nu, nv: grid.nv });
      for (const c of gridCtrls) c.updateDisplay();
    },

    /** A control point was picked in the view: show it in its patch's editor. */
    selectControlPoint(patchName, i, j) {
      bezier?.select(patchName, i, j);
    },

    /** Tick or untick a patch's "pick & drag" toggle (one patch is edited at a time). */
    setEditMode(patchName, on) {
      bezier?.setEditMode(patchName, on);
    },

    /** The edited point moved (a drag in the view): show its numbers. */
    refreshControlPoint(patchName) {
      bezier?.refreshPoint(patchName);
    },

    showLinkLength(chars) {
      share.showLength(chars);
    },
  };
}
