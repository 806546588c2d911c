// Version 4: a Bézier patch's borders given by reference (docs/bezier.md, "Borders by
// reference"). A border names a "surface" patch S(t, v) and its iso-line t = τ (t0 or t1);
// the surface's whole v_range maps linearly onto the edge parameter s in [0, 1] (backwards
// with "reverse"). For an edge with N + 1 control points along it and degree M across it:
//   ring 0 (position): the least-squares fit in the Bernstein basis of degree N of
//     S(τ, v(s)), its two end control points pinned to the corners (shared with the
//     neighbouring borders, so the corners close exactly);
//   ring 1 (tangent):  ring 0 + c_k / M, c the least-squares fit of the cross-boundary
//     derivative D(s) = ρ(s) d S_t(τ, v(s)) into the hole (d = -1 at t0, +1 at t1: the fill
//     continues the surface past its border), with c_0, c_N pinned to the neighbours' ring-0
//     points next to the corners and ρ linear in s, matching their length at the corners;
//   the corner twist (ring 1's second point from each end, shared by two edges) is the mean
//   of the two edges' proposals.
// Every border is recorded as a join (Patch::meets of the surface) for the certificate.
#pragma once
#include "expr/budget.hpp"
#include "scene/scene.hpp"

namespace pdesurf {

// Derives the two outer rings of every Bézier border given by reference into the patch's
// control net (building the net, with a Coons interior, when the scene left it out), records
// the joins and validates the resulting problem. Every node built is charged to `budget`.
// Throws Error(UnknownName | InvalidField | NonFinite | TooLarge) naming the border
// ("patches[4].borders.u0: ...").
void deriveBorders(Scene& scene, ExprBudget& budget);

}  // namespace pdesurf
