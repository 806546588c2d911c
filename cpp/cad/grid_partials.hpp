// S's and B's values and first and second partials on a tensor grid (kFitPartials' order: X,
// X_u, X_v, X_uu, X_vv per coordinate), for the fit (cad/bspline_fit.cpp) and its certificate.
#pragma once
#include <map>
#include <memory>
#include <vector>

#include "expr/program.hpp"

#include "cad/bspline_surface.hpp"
#include "cad/fit_certificate.hpp"
#include "surface/separable_surface.hpp"

namespace pdesurf {

// S on a tensor grid: per coordinate Σ_t G_t^(a)(u_i) g_t^(b)(v_j) as one matrix product per
// partial, general functions by one compiled program over the v values, the pointwise part
// along each row. The u-factors are tabulated and the programs compiled once, then any block
// of v values (the certificate walks its grid in blocks: one block's partials in memory, not
// the whole grid's). `s` must outlive it. at() throws Error(NonFinite) naming the coordinate
// when a value is not finite.
class SurfaceOnGrid {
 public:
  SurfaceOnGrid(const SeparableSurface& s, std::vector<double> u);
  // The first `count` partials of kFitPartials (1: positions; 5: all) at (u, v); the others empty.
  GridPartials at(const std::vector<double>& v, int count = 5) const;
  const std::vector<double>& u() const { return u_; }
  // What one point of at() costs, in multiply-adds: the surface's separable terms and its
  // non-separable part's program instructions (the fit's work budget counts points by it).
  double pointCost() const;

 private:
  const SeparableSurface& s_;
  std::vector<double> u_;
  std::array<std::array<Eigen::MatrixXd, 3>, 3> G_;  // [coordinate][derivative]: mu × terms
  std::array<std::shared_ptr<const ExprProgram>, 3> pointwise_;
};
// The same for a B-spline surface, from its basis functions' collocation matrices.
GridPartials tabulateSpline(const BSplineSurface& b, const std::vector<double>& u, const std::vector<double>& v);
// X - B in place, B's partials made one at a time.
void subtractSpline(const BSplineSurface& b, const std::vector<double>& u, const std::vector<double>& v, GridPartials& X);

}  // namespace pdesurf
