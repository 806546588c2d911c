// The "Ends of “blend”" folders (docs/blends-by-reference.md): per pde patch that has, or
// can have, ends by reference, a subfolder per end. A referenced end shows the surface
// it meets, the trimline (an iso-line or t = τ(v)), continuity, power, scale and flip,
// then the conditions the solver derived from the surface, read-only and refreshed after
// every solve, and "detach" (type them instead). A typed end offers "attach to a surface…".
// Edits go through the handlers, which write the scene and re-solve.
// DOM hooks: data-ends="<patch>" on a patch's folder, data-end="<patch>.<end>" on an end's,
// data-end-field="surface|at|tau|replaces|continuity|power|power-number|power-expression|
// scale|flip|detach|attach" on its controls, data-derived="<axis>.<k>" on a derived field,
// .end-error for a solver message about the end.
import { escapeHtml } from './html-text.js';
import { buildExpressionField } from './expression-field.js';
import { buildPowerControl } from './power-control.js';
import { buildDerivedFields } from './derived-fields.js';
import { buildTauHandles } from './tau-handles.js';
import {
  ENDS, TRIMLINES, ISO_LINES, CONTINUITIES, SCALES,
  readEnd, endOf, canHaveEnds, surfaceNames, curveFromIsoLine, endErrorField, detachRefusal,
} from '../state/ends-edit.js';

const TRIMLINE_LABELS = { t0: 't0 (iso-line)', t1: 't1 (iso-line)', curve: 'curve t = τ(v)' };
const CONTINUITY_LABELS = { position: 'position (G0)', tangency: 'tangency (G1)', curvature: 'curvature (G2)' };
const at01 = (end) => (end === 'u0' ? 0 : 1);

/** lil-gui select options: escaped, unique labels -> values; `current` stays listed. */
function optionsOf(values, labels = {}, current) {
  const list = current === undefined || values.includes(current) ? values : [...values, current];
  const out = {};
  for (const v of list) {
    let label = escapeHtml(labels[v] ?? v);
    while (label in out) label += ' ';
    out[label] = v;
  }
  return out;
}

function note(parent, text) {
  const el = document.createElement('div');
  el.className = 'end-note';
  el.textContent = text; // scene names: never markup
  parent.$children.append(el);
  return el;
}

/**
 * scene: the scene object (read for the current values); solved: the solver's patches
 * (for the derived conditions); handlers:
 *   onField(patchName, end, key, value, typed)  key as web/state/ends-edit.js setEndField;
 *                                               typed: a text field (debounce the solve)
 *   onAttach(patchName, end)
 *   onDetach(patchName, end, derived)           derived: { x: [...], y, z } now shown
 * Returns { update(solved), showSolveError(message), elements(), destroy() }.
 */
export function buildEndFolders(gui, scene, solved, handlers) {
  const folders = [];
  const views = [];
  const patches = Array.isArray(scene?.patches) ? scene.patches : [];

  function clear(view) {
    for (const c of [...view.folder.controllers]) c.destroy();
    for (const f of [...view.folder.folders]) f.destroy();
    for (const el of view.extras) el.remove();
    view.extras = [];
    view.tau = view.powerField = view.derived = view.detach = view.syncPower = null;
  }

  const send = (view, key, value, typed = false) => handlers.onField(view.patch.name, view.end, key, value, typed);

  function select(view, model, key, options, label, title, onChange) {
    const ctrl = view.folder.add(model, key, options).name(escapeHtml(label)).onChange(onChange);
    ctrl.domElement.dataset.endField = key;
    ctrl.domElement.title = title;
    return ctrl;
  }

  // (Re)build an end's controls from the scene: at first, and when its shape changes
  // (iso-line <-> curve, number power <-> expression, attach).
  function fill(view) {
    clear(view);
    const { patch, end, folder } = view;
    const raw = endOf(patch, end);
    if (raw && typeof raw.patch === 'string') {
      // Version 4, a chained end: its conditions come from the patch it continues, once solved.
      view.extras.push(note(folder, `continues “${raw.patch}” ${String(raw.at)} (${raw.continuity === 'curvature' ? 'G2' : 'G1'}): derived from it when it is solved`));
      return;
    }
    const e = readEnd(patch, end);
    if (!e) {
      view.extras.push(note(folder, `typed in Functions “${patch.name}”`));
      if (surfaceNames(scene).length > 0) {
        const attach = folder.add({ attach: () => handlers.onAttach(patch.name, end) }, 'attach').name(escapeHtml('attach to a surface…'));
        attach.domElement.dataset.endField = 'attach';
        attach.domElement.title = 'Derive this end\'s conditions from a surface instead of typing them (its typed conditions go; undo brings them back)';
      }
      return;
    }
    const model = { ...e };
    select(view, model, 'surface', optionsOf(surfaceNames(scene), {}, e.surface), 'surface',
      'the "surface" patch this end meets', (name) => send(view, 'surface', name));
    select(view, model, 'trimline', optionsOf(TRIMLINES, TRIMLINE_LABELS), 'trimline',
      'where the blend meets the surface: one of its iso-line borders, or the curve t = τ(v)', (kind) => {
        if (kind === 'curve') send(view, 'at', curveFromIsoLine(scene, model.surface, e.trimline));
        else send(view, 'at', kind);
        if ((kind === 'curve') !== (e.trimline === 'curve')) fill(view);
        else e.trimline = kind;
      }).domElement.dataset.endField = 'at';
    if (e.trimline === 'curve') {
      view.tau = buildExpressionField(folder, {
        label: 'τ(v)', title: 'the trimline t = τ(v) on the surface, a function of v (parameters allowed)',
        path: `patches[${view.index}].ends.${end}.at.t`, value: e.tau, onEdit: (text) => send(view, 'tau', text, true),
      });
      view.tau.element.dataset.endField = 'tau';
      buildTauHandles(folder, { scene, blend: view.patch, end, tau: e.tau, onTau: (text) => {
        view.tau.element.querySelector('input').value = text;
        send(view, 'tau', text, true);
      } });
      select(view, model, 'replaces', optionsOf(ISO_LINES), 'replaces',
        'the border the curve replaces: the surface is drawn from the curve to its other border', (iso) => send(view, 'replaces', iso));
    }
    select(view, model, 'continuity', optionsOf(CONTINUITIES, CONTINUITY_LABELS), 'continuity',
      'G0 meets the surface, G1 matches its tangent plane, G2 its curvature too (order 6)', (c) => send(view, 'continuity', c));
    const power = buildPowerControl(folder, {
      scene, power: e.power, path: `patches[${view.index}].ends.${end}.power`,
      onPower: (value, typed) => send(view, 'power', value, typed), onKind: () => fill(view),
    });
    view.powerField = power.field;
    view.syncPower = power.sync;
    select(view, model, 'scale', optionsOf(SCALES), 'scale',
      'gap: power 1 gives a tangent as long as the mean gap between the two ends; surface: the surface\'s own speed in t', (s) => send(view, 'scale', s));
    const flip = folder.add(model, 'flip').name(escapeHtml('flip')).onChange((on) => send(view, 'flip', on));
    flip.domElement.dataset.endField = 'flip';
    flip.domElement.title = 'reverse the direction across the join (the blend folds back over the surface)';
    view.derived = buildDerivedFields(folder, { end, surface: e.surface });
    addDetach(view);
    showDerived(view, view.current);
    setStale(view, view.stale);
  }

  function addDetach(view) {
    const { folder, patch, end } = view;
    const detach = folder.add({ detach: () => {
      if (!view.current || view.stale) return;
      const refusal = detachRefusal(end, view.current); // too long to type: keep the reference, say why here
      if (refusal) showMessage(view, refusal);
      else handlers.onDetach(patch.name, end, view.current);
    } }, 'detach').name(escapeHtml('detach: type these conditions'));
    detach.domElement.dataset.endField = 'detach';
    detach.domElement.title = `Turn the derived conditions into typed expressions in Functions “${patch.name}”. `
      + 'Their numbers are the parameters\' current values: the typed conditions no longer follow the sliders or the surface.';
    view.detach = detach;
  }

  function showDerived(view, derived) {
    view.current = derived;
    view.derived?.show(derived);
  }

  function setStale(view, stale) {
    view.stale = stale;
    view.detach?.enable(!stale && Boolean(view.current));
  }

  function showMessage(view, text) {
    view.message.hidden = !text;
    view.message.textContent = text || '';
  }

  patches.forEach((patch, index) => {
    if (!canHaveEnds(scene, patch)) return;
    const folder = gui.addFolder(escapeHtml(`Ends of “${patch.name}”`));
    folder.domElement.classList.add('ends-folder');
    folder.domElement.dataset.ends = patch.name;
    const result = solved.find((p) => p.name === patch.name);
    for (const end of ENDS) {
      const sub = folder.addFolder(escapeHtml(`${end} (u = ${at01(end)})`));
      sub.domElement.dataset.end = `${patch.name}.${end}`;
      const message = document.createElement('div');
      message.className = 'expr-error end-error';
      message.setAttribute('role', 'alert');
      message.hidden = true;
      sub.$children.append(message);
      const view = { patch, index, end, folder: sub, message, extras: [], tau: null, powerField: null, derived: null, detach: null, current: null, stale: false };
      view.current = result?.ends?.[end]?.derived ?? null;
      fill(view);
      views.push(view);
    }
    if (!ENDS.some((end) => readEnd(patch, end))) folder.close(); // nothing by reference yet
    folders.push(folder);
  });

  return {
    /** After a good solve: the derived conditions of that solve; messages go. */
    update(solvedPatches) {
      for (const view of views) {
        const result = solvedPatches.find((p) => p.name === view.patch.name);
        showDerived(view, result?.ends?.[view.end]?.derived ?? null);
        setStale(view, false);
        showMessage(view, null);
        view.tau?.showError(null);
        view.powerField?.showError(null);
        view.syncPower?.();
      }
    },
    /**
     * After a failed solve: a message about an end shows in its folder (beside τ or the
     * power when it names them); detach waits for a good solve (the derived texts are
     * the last good one's). Returns the end ("<patch>.<end>") it landed in, or null.
     */
    showSolveError(message) {
      let landed = null;
      for (const view of views) {
        setStale(view, true);
        view.tau?.showError(null);
        view.powerField?.showError(null);
        showMessage(view, null);
        const field = endErrorField(message, view.index, view.end);
        if (field === null) continue;
        landed = `${view.patch.name}.${view.end}`;
        if (field === 'at' && view.tau) view.tau.showError(message);
        else if (field === 'power' && view.powerField) view.powerField.showError(message);
        else showMessage(view, message);
      }
      return landed;
    },
    /** The folders' root elements, in order (to put rebuilt folders where the old ones were). */
    elements() {
      return folders.map((f) => f.domElement);
    },
    destroy() {
      for (const f of folders) f.destroy();
    },
  };
}
