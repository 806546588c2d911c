// Undo and redo for the page (web/state/history.js holds the steps). Every change to the
// scene or the grid becomes ONE step when its gesture ends, however many solves it caused:
// the page calls touched() on each edited solve, and the state is committed once no pointer
// is down, no text field is being typed in, and the changes have rested (a pointer up, a
// field's change, or REST_MS without a new one). Opening an example, a link or a file is a
// step at once (one that never draws gives its place to the next); the first scene opened is
// the base. Ctrl/Cmd+Z undoes, Ctrl+Shift+Z and Ctrl+Y redo, except in a text field or a
// select (their own undo stays); two toolbar buttons do the same.
import { createHistory } from '../state/history.js';
import { isTextField } from '../keyboard-shortcuts.js';

export const REST_MS = 400;

// Typing goes on while the focus is in a field that takes text; a select's pick is a whole change.
const typing = () => isTextField(document.activeElement) && document.activeElement.tagName !== 'SELECT';

const MAC = typeof navigator !== 'undefined' && /Mac|iPhone|iPad/.test(navigator.platform || '');

/**
 * The context's { state, session, viewer, hooks, titleEl }: a step is the page state as a
 * snapshot { sceneText, grid, exampleId, title }; session.restoreScene(snapshot, camera) puts
 * one back (and re-solves; that solve's touched() is no step since it equals the current
 * one); camera is the view that step was left with, or null; hooks: window.__pdesurf (gets
 * history()).
 */
export function createHistoryFeature({ state, session, viewer, hooks, titleEl }) {
  const read = () => ({ sceneText: state.text(), grid: { ...state.grid }, exampleId: state.exampleId, title: titleEl.textContent });
  const restore = (snapshot, view) => session.restoreScene(snapshot, view);
  const camera = () => viewer.getCamera();
  const history = createHistory();
  // The view each step was left with: a step of another scene comes back framed as it was left.
  const cameras = new WeakMap();
  const pointers = new Set(); // pointers down anywhere on the page
  let timer = 0; // runs from a touched() until the next commit
  let unshown = false; // the current step is an opening that has not drawn yet
  let buttons = null; // { undo, redo } once addButtons() ran
  let held = false; // an edit awaits the solver's verdict: it is no step before it is kept

  function showButtons() {
    if (!buttons) return;
    buttons.undo.disabled = !history.canUndo();
    buttons.redo.disabled = !history.canRedo();
  }

  /** Record the page state as a step if it changed (nothing before the base). */
  function commit() {
    clearTimeout(timer);
    timer = 0;
    if (held || !history.current()) return;
    if (history.push(read())) {
      unshown = false;
      showButtons();
    }
  }

  // A gesture is over when no pointer is down and no text field holds the focus. At a
  // pointer up or a field's change the state is read even if no solve has touched() yet.
  const rested = () => pointers.size === 0 && !typing();
  function commitIfRested() {
    if (rested()) commit();
  }

  // Before the page moves to another step: note the view the current one is left with.
  function leave() {
    const step = history.current();
    const view = camera();
    if (step && view) cameras.set(step, view);
  }

  function apply(snapshot) {
    if (!snapshot) return;
    clearTimeout(timer);
    timer = 0;
    unshown = false;
    restore(snapshot, cameras.get(snapshot) ?? null);
    showButtons();
  }

  function undo() {
    commit(); // an edit still resting is the step undone
    leave();
    apply(history.undo());
  }

  function redo() {
    commit(); // a change since the undo cuts the redo branch: then there is nothing to redo
    leave();
    apply(history.redo());
  }

  window.addEventListener('pointerdown', (e) => {
    if (!typing()) commit(); // a new gesture: the last one ended
    pointers.add(e.pointerId);
  }, true);
  const release = (e) => {
    pointers.delete(e.pointerId);
    commitIfRested();
  };
  window.addEventListener('pointerup', release, true);
  window.addEventListener('pointercancel', release, true);
  window.addEventListener('blur', () => {
    pointers.clear(); // a release outside the window never arrives
    commitIfRested();
  });
  // A typed value ends with its field's change (Enter or leaving it); the focus moves after it.
  const soon = () => setTimeout(commitIfRested, 0);
  document.addEventListener('change', soon, true);
  document.addEventListener('focusout', soon, true);

  // Capture: lil-gui stops keydown from leaving its panel (a focused checkbox, a button).
  window.addEventListener('keydown', (e) => {
    if (!(e.ctrlKey || e.metaKey) || e.altKey) return;
    const key = e.key.toLowerCase();
    const wantsUndo = key === 'z' && !e.shiftKey;
    const wantsRedo = (key === 'z' && e.shiftKey) || (key === 'y' && !e.shiftKey);
    if (!wantsUndo && !wantsRedo) return;
    if (isTextField(e.target) || isTextField(document.activeElement)) return;
    e.preventDefault();
    if (wantsUndo) undo();
    else redo();
  }, true);

  hooks.history = () => ({ canUndo: history.canUndo(), canRedo: history.canRedo(), depth: history.depth(), redoDepth: history.redoDepth() });

  return {
    /** The ↶ and ↷ buttons, in the toolbar's "history" group (web/ui/toolbar.js). */
    addButtons(toolbar) {
      buttons = {
        undo: toolbar.add({ action: 'undo', label: '↶', title: MAC ? 'Undo (⌘Z)' : 'Undo (Ctrl+Z)', onClick: undo, group: 'history' }),
        redo: toolbar.add({ action: 'redo', label: '↷', title: MAC ? 'Redo (⇧⌘Z)' : 'Redo (Ctrl+Shift+Z or Ctrl+Y)', onClick: redo, group: 'history' }),
      };
      showButtons();
    },
    /** The scene or the grid changed (an edited solve): a step once the gesture rests. */
    touched() {
      clearTimeout(timer);
      timer = setTimeout(commitIfRested, REST_MS);
    },
    /**
     * A scene was opened (an example, a link, a file): a step now, or the base if it is the
     * first. An opening that never drew (a link or a file whose scene does not solve, and
     * the page then shows another) gives its place to this one.
     */
    opened() {
      clearTimeout(timer);
      timer = 0;
      leave(); // the view still shows the scene being left
      const changed = unshown ? history.replace(read()) : history.push(read());
      unshown = true;
      if (changed) showButtons();
    },
    /**
     * An edit the solver judges (a picked blend) is in the scene: no step is recorded until
     * release(kept): a kept edit becomes a step once the gesture rests; a refused one was
     * taken back and leaves none.
     */
    hold() {
      held = true;
    },
    release(kept) {
      if (!held) return;
      held = false;
      if (kept) this.touched();
    },
    /** A solve was drawn: the step shown is no longer an opening that may give its place. */
    solved() {
      unshown = false;
    },
    undo,
    redo,
  };
}
