// The page's undo history: a bounded list of snapshots of the page state, with a cursor.
// A snapshot is { sceneText (the scene's JSON), grid: { nu, nv }, exampleId, title }; the
// first one pushed is the base (nothing to undo past it). Pushing after undos cuts off the
// redo branch; pushing a snapshot equal to the current one is no step. No DOM: the page's
// side is web/features/history.js.

export const DEFAULT_CAPACITY = 200; // undoable steps kept; the oldest go first
// And at most this much scene text in all: a scene may be 16 MiB (an imported CAD part), and
// 200 of those would hold gigabytes. The oldest go first; the current step always stays.
export const DEFAULT_MAX_CHARS = 64 << 20;

function freeze({ sceneText, grid, exampleId = null, title = '' }) {
  if (typeof sceneText !== 'string') throw new TypeError('a snapshot needs its scene as JSON text');
  return Object.freeze({
    sceneText,
    grid: Object.freeze({ nu: grid.nu, nv: grid.nv }),
    exampleId,
    title,
  });
}

/** True when two snapshots hold the same page state. */
export function sameSnapshot(a, b) {
  return Boolean(a && b) && a.sceneText === b.sceneText && a.grid.nu === b.grid.nu
    && a.grid.nv === b.grid.nv && a.exampleId === b.exampleId && a.title === b.title;
}

export function createHistory({ capacity = DEFAULT_CAPACITY, maxChars = DEFAULT_MAX_CHARS } = {}) {
  if (!(Number.isInteger(capacity) && capacity >= 1)) throw new RangeError('capacity must be a positive integer');
  let steps = []; // snapshots, oldest first
  let at = -1; // index of the one the page shows
  const charsOf = (list) => list.reduce((n, s) => n + s.sceneText.length, 0);

  return {
    capacity,

    /** Record a new state; false when it equals the current one (no step). */
    push(snapshot) {
      const snap = freeze(snapshot);
      if (sameSnapshot(snap, steps[at])) return false;
      steps = steps.slice(0, at + 1);
      steps.push(snap);
      let chars = charsOf(steps);
      while (steps.length > 1 && (steps.length > capacity + 1 || chars > maxChars)) chars -= steps.shift().sceneText.length;
      at = steps.length - 1;
      return true;
    },

    /**
     * Put `snapshot` in place of the current step (none yet: it becomes the base); if it
     * then equals the step before, the two are one.
     */
    replace(snapshot) {
      if (at < 0) return this.push(snapshot);
      steps = steps.slice(0, at);
      at--;
      this.push(snapshot);
      return true;
    },

    /** Step back: the snapshot to restore, or null at the base. */
    undo() {
      if (at <= 0) return null;
      at--;
      return steps[at];
    },

    /** Step forward again: the snapshot to restore, or null when nothing was undone. */
    redo() {
      if (at >= steps.length - 1) return null;
      at++;
      return steps[at];
    },

    current() {
      return at >= 0 ? steps[at] : null;
    },
    canUndo() {
      return at > 0;
    },
    canRedo() {
      return at < steps.length - 1;
    },
    /** How many undos are possible now. */
    depth() {
      return Math.max(at, 0);
    },
    /** How many redos are possible now. */
    redoDepth() {
      return steps.length - 1 - at;
    },
  };
}
