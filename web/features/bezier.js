// Wiring of the bezier patches' controls: the panel's folders and the view's
// control-point editor both write the scene through the page state, re-solve, and keep
// each other in step (a point picked in the view shows in the panel; a number typed in
// the panel moves the marker). One patch's initial net is edited at a time.
import { AXES, controlPointEntry } from '../state/control-net-edit.js';
import { edits } from '../state/edits.js';

/**
 * Created before the viewer and the panel (they take its handlers); connect(ctx) them
 * once they exist, with the editor's context (editor.js: its state, viewer, panel, doc).
 */
export function createBezierFeature() {
  let ctx = null;
  let solved = new Map(); // patch name -> its last solved result (resolved numbers)
  let editing = null; // the patch whose "pick & drag" is on

  // The scene's numbers; an expression entry shows its last resolved value. A fill whose
  // borders are given by reference may have no control_net: it shows the solved initial net.
  function pointOf(name, i, j) {
    const patch = ctx.state.bezierPatch(name);
    const s = solved.get(name);
    return AXES.map((axis, a) => {
      const v = Array.isArray(patch.control_net) ? controlPointEntry(patch, i, j, axis) : null;
      if (typeof v === 'number') return v;
      return s ? s.initialNet[3 * (i * s.netSize[1] + j) + a] : 0;
    });
  }

  // Every edit goes through the document's door: it re-solves (the solver reports bad values).
  const edit = (write) => ctx.doc.apply(edits.controlNet(write)).ok;

  // The first edit of a net the scene leaves out (a fill with four borders) writes the solved
  // initial net into the scene; the borders still fix their rings over it.
  function writeNet(name) {
    const patch = ctx.state.bezierPatch(name);
    if (Array.isArray(patch.control_net)) return;
    const s = solved.get(name);
    if (!s) throw new Error(`${name} has no solved net yet`);
    const round = (x) => Math.round(x * 1e7) / 1e7;
    patch.control_net = Array.from({ length: s.netSize[0] * s.netSize[1] }, (_, k) => [0, 1, 2].map((a) => round(s.initialNet[3 * k + a])));
  }

  const viewerHandlers = {
    pointOf,
    onPick(name, i, j) {
      ctx.panel.selectControlPoint(name, i, j);
      ctx.viewer.editControlPoint(name, i, j);
    },
    // Only the coordinates the drag changed are written (an expression entry the gizmo
    // did not move stays an expression), rounded as the examples are: short links.
    onMove(name, i, j, xyz) {
      const old = pointOf(name, i, j);
      const write = () => writeNet(name) || AXES.forEach((axis, a) => {
        if (xyz[a] !== old[a]) ctx.state.setControlPointCoordinate(name, i, j, axis, Math.round(xyz[a] * 1e6) / 1e6);
      });
      if (edit(write)) ctx.panel.refreshControlPoint(name);
    },
  };

  const panelHandlers = {
    pointOf,
    onOverlay: (name, key, on) => ctx.viewer.setOverlay(name, key, on),
    onNumber: (name, key, value) => edit(() => ctx.state.setBezierNumber(name, key, value)),
    onRegionWeights: (name, regions) => edit(() => ctx.state.setRegionWeights(name, regions)),
    onEditMode(name, on, { i, j }) {
      if (on && editing && editing !== name) ctx.panel.setEditMode(editing, false);
      if (on) editing = name;
      else if (editing === name) editing = null;
      if (on) ctx.viewer.editControlPoint(name, i, j);
      else if (!editing) ctx.viewer.editControlPoint(null);
    },
    onSelect(name, i, j) {
      if (editing === name) ctx.viewer.editControlPoint(name, i, j);
    },
    onCoordinate(name, i, j, axis, value) {
      if (edit(() => writeNet(name) || ctx.state.setControlPointCoordinate(name, i, j, axis, value)) && editing === name) {
        ctx.viewer.editControlPoint(name, i, j); // the marker follows the typed number
      }
    },
  };

  return {
    viewerHandlers,
    panelHandlers,
    pointOf,
    connect(parts) {
      ctx = parts;
      // A feature of the document: it hears of new scenes and solves itself.
      ctx.doc.on('opened', () => this.reset());
      ctx.doc.on('solved', (result) => this.solvedPatches(result.patches));
    },
    /** Before the viewer draws a solve: keep its resolved numbers for pointOf. */
    solvedPatches(patches) {
      solved = new Map(patches.filter((p) => p.kind === 'bezier').map((p) => [p.name, p]));
    },
    /** A new scene: nothing edited. */
    reset() {
      solved = new Map();
      editing = null;
    },
  };
}
