// The page's one door for changes: every edit of the scene (a slider, a typed field, adding a
// surface, picking two borders, moving a surface, deleting) and of the selection goes through
// apply() or select(). The door runs the edit, puts the scene back if it throws, and signals
// the result; the solve scheduler, the undo history, the link, the panel and the outliner
// subscribe (web/editor.js composes them) instead of each handler calling them on its own.
//
// An edit (made by a factory of web/state/edits.js): {
//   type:      what kind of edit it is (EDIT_TYPES; code branches on it)
//   name:      what it does, for messages ("add a cylinder")
//   run(state) -> result     changes the scene (web/state/scene-state.js); throws to refuse
//   solve:     'now' (default) | 'typed' (after the keys pause) | 'none'
//   structure: true when patches or parameters are added, removed or renamed (the panel's
//              scene folders and the outliner are rebuilt)
//   checked:   true when the solver is the judge (a blend picked from two borders): if the
//              next solve fails, the scene goes back to what it was and the error is
//              reported as this edit's refusal
// }
// Signals: SIGNALS below, declared once; emitting or subscribing to another name throws.

/** A refusal's text: a solver error carries its code (InvalidField, …), an edit's own is an Error. */
export const messageOf = (err) => (err && err.code ? `${err.code}: ${err.message}` : err && err.message ? err.message : String(err));

/** Every signal the page emits, with what it carries. */
export const SIGNALS = Object.freeze({
  changed: '(edit, result): an edit went through the door',
  refused: '(error, edit): an edit was refused (by itself, or by the solver for a checked edit)',
  selection: '(name | null): the selected patch',
  judging: '(edit): a checked edit awaits the solver',
  judged: '(kept): its verdict',
  reverted: '(edit): a checked edit the solver refused was put back',
  opened: '(scene, { exampleId, title }): the scene session opened a scene',
  restored: '(scene): undo or redo put a scene back',
  solved: '(result, job): a solve came back (the meshes, before they are drawn)',
  drawn: '(result, job): its meshes are drawn',
  certified: '(report, job): the join report of the drawn scene arrived',
});

/** Every type an edit may have (the factories of ./edits.js make them): the door refuses any other. */
export const EDIT_TYPES = Object.freeze(new Set(['set-parameter', 'add-parameter', 'remove-parameter', 'set-grid', 'operator-param', 'operator-order', 'method',
  'end-field', 'attach-end', 'detach-end', 'expression', 'control-net', 'add-surface', 'rename', 'duplicate', 'delete', 'blend', 'fill', 'place']));

function known(signal) {
  if (!Object.hasOwn(SIGNALS, signal)) throw new Error(`unknown signal ${JSON.stringify(signal)} (web/state/document.js declares them)`);
}

export function createDocument(state) {
  const subscribers = new Map();
  let selection = null;
  let pendingCheck = null; // { edit, before } until the next solve says yes or no

  function emit(signal, ...args) {
    known(signal);
    for (const fn of subscribers.get(signal) || []) fn(...args);
  }

  // In place: the panel and the wiring hold the scene object itself.
  function restore(text) {
    const scene = state.scene;
    for (const key of Object.keys(scene)) delete scene[key];
    Object.assign(scene, JSON.parse(text));
  }

  const doc = {
    state,

    /** Tell the subscribers of `signal` (one of SIGNALS: the scene session's 'opened', 'solved', 'drawn', …). */
    emit,

    /** Subscribe to a signal; returns the unsubscribe function. */
    on(signal, fn) {
      known(signal);
      if (!subscribers.has(signal)) subscribers.set(signal, new Set());
      subscribers.get(signal).add(fn);
      return () => subscribers.get(signal).delete(fn);
    },

    /** Run an edit through the door: { ok, result } or { ok: false, error }. */
    apply(edit) {
      if (!EDIT_TYPES.has(edit?.type)) throw new Error(`an edit of unknown type ${JSON.stringify(edit?.type)} (web/state/edits.js makes them)`);
      if (!state.scene) return { ok: false, error: new Error('no scene is open') };
      const before = JSON.stringify(state.scene);
      let result;
      try {
        result = edit.run ? edit.run(state) : undefined;
      } catch (error) {
        restore(before);
        emit('refused', error, edit);
        return { ok: false, error };
      }
      if (edit.checked) {
        pendingCheck = { edit, before };
        emit('judging', edit);
      }
      emit('changed', edit, result);
      return { ok: true, result };
    },

    /** The solver's verdict on the scene as it now is (scene-session.js calls it after every solve). */
    solved(ok, error) {
      const check = pendingCheck;
      pendingCheck = null;
      if (!check) return false;
      emit('judged', ok);
      if (ok) return false;
      restore(check.before);
      emit('refused', error, check.edit);
      emit('reverted', check.edit);
      return true;
    },

    /** Another scene opened (or an undo put one back): no edit is pending any more. */
    reset() {
      if (pendingCheck) emit('judged', false);
      pendingCheck = null;
      doc.select(null);
    },

    /** The selected patch (the outliner's row, the view's highlight, its placement folder). */
    select(name) {
      if (name === selection) return;
      selection = name;
      emit('selection', name);
    },

    selection: () => selection,
  };
  return doc;
}
