// The kinds of patch the page knows, in one table: what each is called, whether the core
// solves it (else it is a primary surface, typed), whether it is a PDE (re-solved by an edit
// upstream), which borders can be picked on it, and whether it can be placed. The outliner,
// the meshes, the border picker, the session and building read it (issue 39: six files kept
// their own lists and disagreed on what a surface is). References between patches:
// ./patch-references.js. A new kind: one entry here, its references there, and one in the
// core's table (cpp/scene/patch_kinds.cpp).

const KINDS = Object.freeze({
  surface: { label: 'surface', solved: false, pde: false, borders: ['t0', 't1'], placeable: true },
  ruled: { label: 'ruled', solved: false, pde: false, borders: ['t0', 't1'], placeable: false },
  separable: { label: 'separable', solved: false, pde: false, borders: ['t0', 't1'], placeable: false },
  pde: { label: 'blend', solved: true, pde: true, borders: ['u0', 'u1'], placeable: false },
  fill: { label: 'fill', solved: true, pde: true, borders: [], placeable: false },
  bezier: { label: 'Bézier', solved: true, pde: false, borders: ['u0', 'u1', 'v0', 'v1'], placeable: false },
});

// A kind the table does not have (a newer scene) is drawn as a typed surface, named as it is.
const unknown = (kind) => ({ label: String(kind), solved: false, pde: false, borders: ['t0', 't1'], placeable: false });

/** The kinds in the table (the core's, cpp/scene/patch_kinds.hpp, are the same: tests/js). */
export const KIND_NAMES = Object.freeze(Object.keys(KINDS));
/** The table's entry for `kind`. */
export const kindInfo = (kind) => (Object.hasOwn(KINDS, kind) ? KINDS[kind] : unknown(kind));
/** A primary surface (typed, not solved): a blend's or fill's borders lie on it. */
export const isSurfaceKind = (kind) => !kindInfo(kind).solved;
