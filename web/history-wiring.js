// Undo and redo for the page (web/state/history.js holds the steps). Every change to the
// scene or the grid becomes ONE step when its gesture ends, however many solves it caused:
// the page calls touched() on each edited solve, and the state is committed once no pointer
// is down, no text field is being typed in, and the changes have rested (a pointer up, a
// field's change, or REST_MS without a new one). Opening an example or a link is a step at
// once; the first scene opened is the base. Ctrl/Cmd+Z undoes, Ctrl+Shift+Z and Ctrl+Y redo,
// except in a text field or a select (their own undo stays); two toolbar buttons do the same.
import { createHistory } from './state/history.js';

export const REST_MS = 400;

const NOT_TEXT = new Set(['checkbox', 'radio', 'range', 'button', 'submit', 'reset', 'color', 'file', 'image']);

/** An element that takes typed text: its keys and its Ctrl+Z are its own. */
function takesText(el) {
  if (!el || el.nodeType !== 1) return false;
  if (el.isContentEditable || el.tagName === 'TEXTAREA') return true;
  return el.tagName === 'INPUT' && !NOT_TEXT.has((el.type || 'text').toLowerCase());
}
const isFormField = (el) => takesText(el) || (el && el.tagName === 'SELECT');

const MAC = typeof navigator !== 'undefined' && /Mac|iPhone|iPad/.test(navigator.platform || '');

/**
 * toolbar: web/ui/toolbar.js; read() -> the page state as a snapshot { sceneText, grid,
 * exampleId, title }; restore(snapshot) puts one back (and re-solves; that solve's touched()
 * is no step since it equals the current one); hooks: window.__pdesurf (gets history()).
 */
export function createHistoryWiring({ toolbar, read, restore, hooks }) {
  const history = createHistory();
  const pointers = new Set(); // pointers down anywhere on the page
  let timer = 0; // runs from a touched() until the next commit
  let replaceNext = false; // the next opening takes the place of the current step (a link that failed)

  const undoButton = toolbar.add({
    action: 'undo', label: '↶', title: MAC ? 'Undo (⌘Z)' : 'Undo (Ctrl+Z)', onClick: () => undo(), group: 'history',
  });
  const redoButton = toolbar.add({
    action: 'redo', label: '↷', title: MAC ? 'Redo (⇧⌘Z)' : 'Redo (Ctrl+Shift+Z or Ctrl+Y)', onClick: () => redo(), group: 'history',
  });
  function showButtons() {
    undoButton.disabled = !history.canUndo();
    redoButton.disabled = !history.canRedo();
  }
  showButtons();

  /** Record the page state as a step if it changed (nothing before the base). */
  function commit() {
    clearTimeout(timer);
    timer = 0;
    if (!history.current()) return;
    if (history.push(read())) showButtons();
  }

  // A gesture is over when no pointer is down and no text field holds the focus. At a
  // pointer up or a field's change the state is read even if no solve has touched() yet.
  const rested = () => pointers.size === 0 && !takesText(document.activeElement);
  function commitIfRested() {
    if (rested()) commit();
  }

  function apply(snapshot) {
    if (!snapshot) return;
    clearTimeout(timer);
    timer = 0;
    restore(snapshot);
    showButtons();
  }

  function undo() {
    commit(); // an edit still resting is the step undone
    apply(history.undo());
  }

  function redo() {
    commit(); // a change since the undo cuts the redo branch: then there is nothing to redo
    apply(history.redo());
  }

  window.addEventListener('pointerdown', (e) => {
    if (!takesText(document.activeElement)) commit(); // a new gesture: the last one ended
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
    if (isFormField(e.target) || isFormField(document.activeElement)) return;
    e.preventDefault();
    if (wantsUndo) undo();
    else redo();
  }, true);

  hooks.history = () => ({ canUndo: history.canUndo(), canRedo: history.canRedo(), depth: history.depth(), redoDepth: history.redoDepth() });

  return {
    /** The scene or the grid changed (an edited solve): a step once the gesture rests. */
    touched() {
      clearTimeout(timer);
      timer = setTimeout(commitIfRested, REST_MS);
    },
    /** Before another scene replaces this one: what was changed in it is a step of its own. */
    commit() {
      if (!replaceNext) commit();
    },
    /** A scene was opened (an example or a link): a step now, or the base if it is the first. */
    opened() {
      clearTimeout(timer);
      timer = 0;
      const changed = replaceNext ? history.replace(read()) : history.push(read());
      replaceNext = false;
      if (changed) showButtons();
    },
    /** The scene just opened cannot be shown (a link that does not solve): the next opening replaces its step. */
    replaceNextOpening() {
      replaceNext = true;
    },
    undo,
    redo,
  };
}
