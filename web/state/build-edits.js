// The building edits of the catalogue (./edits.js says what an edit is): adding, renaming,
// duplicating and deleting patches, blends and fills picked from borders, placements. One
// undo step each; their result is the new patch's name. In the editor's chunk (they bring the
// building modules with them).
import { addSurface } from './surface-library.js';
import { addBlend, addFill, addLoopFill } from './scene-join.js';
import { renamePatch, duplicatePatch, deletePatch, setPlacement } from './scene-build.js';
import { dragPlacement } from './placement.js';

const building = { structure: true, build: true };

export const buildEdits = Object.freeze({
  addSurface: (kind, options, label) => ({ type: 'add-surface', name: `add a ${label}`, run: (s) => addSurface(s.scene, kind, options), ...building }),
  rename: (old, next) => ({ type: 'rename', name: 'rename', run: (s) => renamePatch(s.scene, old, next), ...building }),
  duplicate: (name) => ({ type: 'duplicate', name: 'duplicate', run: (s) => duplicatePatch(s.scene, name), ...building }),
  delete: (name, dependents, solved) => ({ type: 'delete', name: 'delete', run: (s) => deletePatch(s.scene, name, { dependents, solved }), ...building }),
  // The solver judges what the page cannot (a border where ∂S/∂t vanishes).
  blend: (a, b, options) => ({ type: 'blend', name: 'blend', run: (s) => addBlend(s.scene, a, b, options), ...building, checked: true }),
  // endpoints: the drawn borders' ends (a border not drawn yet cannot be filled).
  fill: (borders, endpoints, options, tolerance) => ({
    type: 'fill',
    name: 'fill',
    run: (s) => {
      if (endpoints.some((e) => !e)) throw new Error('a border that is not drawn yet cannot be filled: wait for the solve');
      return options.kind === 'pde'
        ? addLoopFill(s.scene, borders, endpoints, { continuity: options.continuity, tolerance })
        : addFill(s.scene, borders, endpoints, { tolerance });
    },
    ...building,
    checked: true,
  }),
  // Typed in the Placement folder, or dragged with the gizmo (a placement naming parameters moves them).
  place: (name, placement) => ({ type: 'place', name: 'place', run: (s) => setPlacement(s.scene, name, placement), build: true }),
  drag: (name, now) => ({ type: 'place', name: 'place', run: (s) => dragPlacement(s.scene, name, now), build: true }),
});
