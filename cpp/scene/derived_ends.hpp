// Version 3: the conditions of blend ends given by reference (docs/blends-by-reference.md).
// For an end that meets surface S(t, v) at the trimline t = tau(v) (an iso-line t0 or t1, or
// a curve), with continuation sign d (the blend lies beyond the trimline, on the side away
// from the surface), power p(v) and scale k:
//   X    = S(tau, v)
//   X_u  = ±d k p S_t(tau, v)       (+ at u0, - at u1: the u-direction points into the blend at u0)
//   X_uu = k² p² S_tt(tau, v)
// i.e. the blend follows the surface's own t-curves continued past the trimline to first
// (tangency) or second (curvature) order, so the join is G1 or G2 by construction. k makes
// power 1 mean "a tangent as long as the mean distance between the two ends' curves" (scale
// "gap", the default), or k = 1 (scale "surface": the surface's own t-speed).
// An end asking less than the operator carries gets the ruled surface's conditions:
// X_u = X(1, v) - X(0, v), X_uu = 0.
#pragma once
#include "expr/budget.hpp"
#include "scene/scene.hpp"

namespace pdesurf {

// Derives every referenced end of every pde patch into its boundary slots, records the joins
// (meets, one per end) for the certificate and trims surfaces met along a curve (their t
// becomes 0..1 from the trimline), in an order that does not depend on the patches': every
// end is derived and checked (scene/trimline_checks.hpp) on the untrimmed surfaces, the joins
// are recorded in the trimmed parametrisation, the trims come last. A surface is trimmed along
// one curve at most, and the border it replaces is met by no other end. Throws
// Error(UnknownName | InvalidField | NonFinite | TooLarge) naming the end and, where it
// applies, the v at fault. Every node built is charged to `budget` (the scene's, which
// parseScene makes current and shares with deriveBorders).
void deriveEnds(Scene& scene, ExprBudget& budget);

}  // namespace pdesurf
