// The scene object in memory is the page state: sliders write into it, and
// JSON.stringify(scene) is exactly what the solver sees.

const AXES = ['x', 'y', 'z'];

export function createSceneState() {
  const state = {
    scene: null,
    exampleId: null,
    grid: { nu: 64, nv: 64 },

    /** Replace the whole scene (example change). */
    setScene(scene, exampleId) {
      state.scene = scene;
      state.exampleId = exampleId;
    },

    /** The pde patches of the scene, in scene order. */
    pdePatches() {
      return (state.scene?.patches || []).filter((p) => p && p.kind === 'pde');
    },

    /**
     * Set one component of operator field b|c|d of a pde patch. A scalar (one value
     * for x, y and z) becomes a 3-array so the other two components keep their value.
     */
    setOperatorComponent(patchName, field, axis, value) {
      const patch = state.pdePatches().find((p) => p.name === patchName);
      if (!patch) throw new Error(`no pde patch named ${JSON.stringify(patchName)}`);
      patch.operator = patch.operator || {};
      const current = patch.operator[field];
      const arr = Array.isArray(current) ? current.slice() : [current ?? 0, current ?? 0, current ?? 0];
      arr[AXES.indexOf(axis)] = value;
      patch.operator[field] = arr;
    },

    /** The text handed to the solver. */
    text() {
      return JSON.stringify(state.scene);
    },
  };
  return state;
}

