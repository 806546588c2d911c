// Where a surface may be only C0 across an iso-line v = const: the zeros, on (v0, v1), of the
// arguments of abs() and sign() in its general functions of v (a border typed or derived
// piecewise, a fill's corners). A smooth spline converges only linearly across a crease, so
// the fit puts a knot of full multiplicity there (bspline_fit.cpp).
#pragma once
#include <vector>

#include "surface/separable_surface.hpp"

namespace pdesurf {

// Sorted, distinct (kinks within 1e-6 of the range are one), strictly inside (v0, v1); at most kMaxCreases
// (more, and the rest are left to refinement).
constexpr int kMaxCreases = 64;
// kinkAtEnds: set when a kink argument vanishes at v0 or v1 too: S_v there is then the mean of
// two sides (sign(0) = 0), not a one-sided derivative.
std::vector<double> findCreases(const SeparableSurface& s, bool* kinkAtEnds = nullptr);

}  // namespace pdesurf
