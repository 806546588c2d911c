// S's and B's values and first and second partials on a tensor grid (kFitPartials' order: X,
// X_u, X_v, X_uu, X_vv per coordinate), for the fit (cad/bspline_fit.cpp) and its certificate.
#pragma once
#include <vector>

#include "cad/bspline_surface.hpp"
#include "cad/fit_certificate.hpp"
#include "surface/separable_surface.hpp"

namespace pdesurf {

// Per coordinate Σ_t G_t^(a)(u_i) g_t^(b)(v_j) as one matrix product per partial, general
// functions by one compiled program over every v, the pointwise part along each row. Throws
// Error(NonFinite) naming the coordinate when a value is not finite.
GridPartials tabulateSurface(const SeparableSurface& s, const std::vector<double>& u, const std::vector<double>& v);
// The same for a B-spline surface, from its basis functions' collocation matrices.
GridPartials tabulateSpline(const BSplineSurface& b, const std::vector<double>& u, const std::vector<double>& v);
// X - B in place, B's partials made one at a time.
void subtractSpline(const BSplineSurface& b, const std::vector<double>& u, const std::vector<double>& v, GridPartials& X);

}  // namespace pdesurf
