// Building a model in the page: the Build folder (new scene, Add, blend two borders, fill a
// loop), the Model outliner, the selected surface's placement (numbers and the view's gizmo)
// and picking borders in the view. Every change is one edit through the document's door
// (web/state/document.js), which re-solves, records the undo step and updates the link;
// this module only subscribes to the door and turns the user's asks into edits.
import { buildBuildFolder } from '../ui/build-controls.js';
import { buildOutliner } from '../ui/outliner.js';
import { buildPlacementFolder } from '../ui/placement-controls.js';
import { libraryEntry } from '../state/surface-library.js';
import { bordersOfPatch } from '../state/scene-join.js';
import { newScene, dependentsOf, unusedParameters } from '../state/scene-build.js';
import { previewMesh, pivotOf } from '../viewer/placement-gizmo.js';
import { placementValues } from '../state/placement.js';
import { edits } from '../state/edits.js';
import { buildEdits } from '../state/build-edits.js';
import { messageOf } from '../state/document.js';
import { bodyText } from '../state/join-report.js';
import { kindInfo, isSurfaceKind } from '../state/patch-kinds.js';

// The patches a placement can move.
const surfacesOf = (scene) => (scene?.patches || []).filter((p) => p && kindInfo(p.kind).placeable);

/** The context's { doc, panel, viewer, hooks, session (openBuilt(scene, title) opens a new scene) } */
export function createBuildFeature({ doc, panel, viewer, hooks, session }) {
  const openBuilt = (scene, title) => session.openBuilt(scene, title);
  const { state } = doc;
  let drawn = []; // the last good solve's patches
  let pickMode = null; // 'blend' | 'fill' | null
  let gizmoMode = null; // 'translate' | 'rotate' | 'scale' | null
  let placement = null; // the selected surface's placement folder
  const hidden = new Set();
  // The scene text of the drawn solve: a gizmo drag previews from the placement its mesh was
  // solved at. Read only while a drag needs it (not on every solve).
  let drawnText = null;
  let drawnScene = null; // drawnText parsed, once
  const drawnPlacement = (name) => {
    if (!drawnScene && drawnText) drawnScene = JSON.parse(drawnText);
    return placementValues(drawnScene, surfacesOf(drawnScene).find((p) => p.name === name)?.placement);
  };

  // Building edits (state/build-edits.js): one undo step each; the answer shows beside the
  // choices (said: its text from the edit's result).
  function build(edit, said) {
    const r = doc.apply(edit);
    if (r.ok) folder.say(typeof said === 'function' ? said(r.result) : '');
    return r;
  }

  const folder = buildBuildFolder(panel.gui, {
    onNew: () => {
      doc.select(null);
      openBuilt(newScene(), 'untitled scene');
    },
    onAdd: (kind, options = {}) => {
      const name = kind === 'custom' ? 'custom surface' : libraryEntry(kind)?.label ?? kind;
      const r = build(buildEdits.addSurface(kind, options, name), (n) => `added ${n}`);
      if (r.ok) doc.select(r.result);
    },
    onBlend: (a, b, options) => makeBlend(a, b, options),
    onFill: (borders, options) => makeFill(borders, options),
    onPickMode: (kind) => setPickMode(kind),
  });

  const outliner = buildOutliner(panel.gui, {
    onSelect: (name) => doc.select(name),
    onRename: (old, next) => {
      const r = build(buildEdits.rename(old, next));
      if (r.ok && doc.selection() === old) doc.select(next);
      if (!r.ok) refresh(); // the name field shows the old name again
    },
    onVisible: (name, on) => {
      if (on) hidden.delete(name);
      else hidden.add(name);
      viewer.setPatchVisible(name, on);
    },
    onDuplicate: (name) => {
      const r = build(buildEdits.duplicate(name), (n) => `${name} duplicated as ${n}`);
      if (r.ok) doc.select(r.result);
    },
    onDelete: (name, dependents) => {
      if (doc.selection() === name) doc.select(null);
      build(buildEdits.delete(name, dependents, drawn));
    },
    onRemoveParameter: (name) => build({ ...edits.removeParameter(name), build: true }),
  });
  panel.keepAfterShare(folder.folder.domElement, outliner.folder.domElement);

  function makeBlend(a, b, options) {
    const r = build(buildEdits.blend(a, b, options), (n) => `${n}: ${a.surface} ${a.at} to ${b.surface} ${b.at}`);
    folder.clearChoices();
    viewer.borders.highlight([]);
    if (r.ok) doc.select(r.result);
  }

  function makeFill(borders, options = {}) {
    const list = viewer.borders.list();
    const drawnBorders = borders.map((b) => list.find((d) => d.patch === b.surface && d.border === b.at));
    const endpoints = drawnBorders.map((d) => d?.endpoints);
    // Ends closer than 1e-3 of the borders' size meet (float32 vertices: a closed border's two
    // ends may differ in the last digit).
    const tolerance = 1e-3 * Math.max(0, ...drawnBorders.map((d) => d?.extent ?? 0));
    const r = build(buildEdits.fill(borders, endpoints, options, tolerance), (n) => `${n} fills ${borders.map((b) => `${b.surface} ${b.at}`).join(', ')}`);
    folder.clearChoices();
    viewer.borders.highlight([]);
    if (r.ok) doc.select(r.result);
  }

  // Picking in the view: hovering only draws (never a solve); each click fills the next choice.
  function setPickMode(kind) {
    pickMode = kind;
    if (!kind) {
      viewer.borders.disable();
      viewer.borders.highlight([]);
      return;
    }
    // Every drawn border may be picked, but a Bézier fill's lie on surfaces (its rings of
    // control points are derived from them): while one is being made, only theirs.
    const kindOf = (name) => (state.scene?.patches || []).find((p) => p && p.name === name)?.kind;
    viewer.borders.enable({
      filter: (patch) => !(pickMode === 'fill' && folder.fillOptions().kind === 'bezier') || isSurfaceKind(kindOf(patch)),
      onPick: (pick) => {
        const border = { surface: pick.patch, at: pick.border };
        const chosen = folder.picked(pickMode, border);
        viewer.borders.highlight(chosen.map((c) => ({ patch: c.surface, border: c.at })));
        if (pickMode === 'blend' && chosen.length === 2) makeBlend(chosen[0], chosen[1], folder.blendOptions());
        // A Bézier fill is made at the fourth pick; a PDE fill at the eighth, or by its button.
        const options = folder.fillOptions();
        if (pickMode === 'fill' && chosen.length === (options.kind === 'pde' ? 8 : 4)) makeFill(chosen, options);
      },
    });
  }

  function showPlacementOf(name) {
    placement?.destroy();
    placement = null;
    viewer.placement.detach();
    const patch = surfacesOf(state.scene).find((p) => p.name === name);
    if (!patch) return;
    placement = buildPlacementFolder(panel.gui, name, patch.placement, {
      onPlacement: (n, p) => build(buildEdits.place(n, p)),
      onMode: (mode) => {
        gizmoMode = mode;
        attachGizmo(name);
      },
    }, gizmoMode ?? 'off');
    panel.gui.$children.insertBefore(placement.folder.domElement, outliner.folder.domElement.nextSibling);
    attachGizmo(name);
  }

  // A gizmo drag re-solves as it goes (blends by reference follow the surface live, and
  // the whole drag is one undo step, like a slider's); between solves the drawn mesh is
  // moved by the placement's change since the solve it shows (a preview, no solve).
  function attachGizmo(name) {
    if (viewer.placement.dragging()) return; // a solve drawn mid-drag leaves the drag alone
    viewer.placement.detach();
    const patch = surfacesOf(state.scene).find((p) => p.name === name);
    const mesh = viewer.meshOf(name);
    if (!gizmoMode || !patch || !mesh) return;
    viewer.placement.setMode(gizmoMode);
    // The gizmo works in numbers; a placement naming parameters moves them (dragPlacement).
    const place = (now) => doc.apply(buildEdits.drag(name, now));
    viewer.placement.attach(name, placementValues(state.scene, patch.placement), pivotOf(mesh), {
      onDrag: (now) => {
        previewMesh(viewer.meshOf(name), drawnPlacement(name), now);
        place(now);
      },
      onCommit: (now) => place(now),
    });
  }

  function refresh() {
    const scene = state.scene;
    // Every border a blend or a fill can meet: surfaces' t0/t1, pde patches' ends, Bézier borders.
    const patches = (scene?.patches || []).filter(Boolean);
    folder.setBorders(patches.flatMap((p) => bordersOfPatch(p).map((at) => ({ surface: p.name, at }))));
    outliner.show((scene?.patches || []).filter(Boolean), (n) => dependentsOf(scene, n).map((d) => d.patch), unusedParameters(scene));
    outliner.select(doc.selection());
  }

  doc.on('changed', (edit) => {
    if (edit.structure) refresh();
    if (edit.type === 'place' || edit.structure) placement?.update(surfacesOf(state.scene).find((p) => p.name === doc.selection())?.placement);
  });
  doc.on('reverted', () => refresh());
  doc.on('refused', (err, edit) => {
    if (edit.build) folder.say(`cannot ${edit.name}: ${messageOf(err)}`, true);
  });
  // The selected patch's own folders (its operator, ends, functions, net) open.
  function revealFolders(name) {
    if (!name) return;
    const own = panel.gui.folders.filter((f) => f.$title.textContent.endsWith(`“${name}”`));
    for (const f of own) f.open();
  }

  doc.on('selection', (name) => {
    outliner.select(name);
    viewer.select(name);
    showPlacementOf(name);
    revealFolders(name);
  });

  // A click on a patch in the view selects it; on the background, nothing is selected.
  viewer.onPatchClick((name) => doc.select(name));

  // New scenes, undo steps within one, and drawn solves: the lists and the gizmo follow.
  doc.on('opened', () => api.sceneShown());
  doc.on('restored', () => api.sceneShown());
  doc.on('drawn', (result, job) => api.drawn(result.patches, job.scene, result.report));
  doc.on('certified', (report) => outliner.showBodies((report?.bodies ?? []).map(bodyText)));

  hooks.build = () => ({ pickMode, gizmoMode, selection: doc.selection(), hidden: [...hidden] });

  const api = {
    /** Another scene is on screen (opened, undone, redone): lists follow it. */
    sceneShown() {
      hidden.clear();
      refresh();
      showPlacementOf(doc.selection());
    },
    /** A good solve of `sceneText` was drawn: borders and the gizmo's mesh are the new ones. */
    drawn(patches, sceneText, report) {
      drawn = patches;
      if (report) outliner.showBodies((report.bodies ?? []).map(bodyText)); // else kept until certified
      drawnText = sceneText;
      drawnScene = null;
      for (const name of hidden) viewer.setPatchVisible(name, false);
      if (doc.selection() && gizmoMode) attachGizmo(doc.selection());
    },
  };
  return api;
}
