// A certified B-spline fit of a separable surface in its own (u, v): least squares on a grid
// aligned with the knot spans, knots halved where the error is largest, until a bound of
// max |S - B| over the whole parameter rectangle (not only at samples) is within the
// tolerance. The bound (fit_certificate.hpp, docs/cad-export.md): on every grid cell,
//   |e| <= max over the corners |e| + h²/8 max|e_uu| + k²/8 max|e_vv|, e = S - B,
// with max|e_uu|, max|e_vv| bounded the same way one level down, and the fourth derivatives
// there bounded rigorously: S's from its closed form (derivative_bounds.hpp), B's from its
// differenced poles (the convex hull of a B-spline).
#pragma once
#include <Eigen/Core>
#include <vector>

#include "cad/fit_work.hpp"
#include "cad/bspline_surface.hpp"
#include "surface/separable_surface.hpp"

namespace pdesurf {

struct FitOptions {
  double tolerance = 0.0;  // absolute, in scene units; positive and finite
  int degree = 5;          // 3 or 5, in both directions
  // Normals of S and B at the grid points of the borders u0 and u1 (where ends join) within
  // this angle too (measured, not bounded between points): what keeps G1 joins G1 once written.
  double normalToleranceDeg = 0.01;
  // The scene's work budget (cad/fit_work.hpp) this fit charges, if any.
  FitWork* work = nullptr;
};

struct FitReport {
  double deviation = 0.0;         // certified: max |S - B| over the whole patch is at most this
  double sampledDeviation = 0.0;  // the largest |S - B| at the certificate's grid points
  double normalDeviationDeg = 0.0;  // the largest angle between S's and B's normals at the u-borders' grid points
  bool normalsMet = true;         // normalDeviationDeg within FitOptions::normalToleranceDeg
  double scale = 0.0;             // the patch's bounding-box diagonal (from the grid)
  int iterations = 0;
  long gridPoints = 0;            // of the last certificate
  int creases = 0;                // v-lines where S is only C0, each a knot of full multiplicity
  bool periodicV = false;         // fitted with a periodic basis in v (written clamped at the seam)
  bool exact = false;             // a Bézier net written as it is
};

// Limits (docs/limits.md): spans per direction, and grid points of one certificate, checked
// before each refinement is done.
constexpr int kFitMaxSpans = 512;
constexpr long kFitMaxGridPoints = 1L << 20;
constexpr int kFitMaxIterations = 24;

// Throws Error(InvalidField) for a tolerance that is not positive and finite or a degree other
// than 3 or 5, Error(TooLarge) naming the deviation reached when a limit stops the refinement
// short of the tolerance (short of the normals' target only, the fit is returned: normalsMet),
// Error(NonFinite) when the surface is not finite on the grid.
BSplineSurface fitSurface(const SeparableSurface& s, const FitOptions& options, FitReport* report);

// A Bézier patch of degrees (n, m) (net row i major, (n+1)(m+1) poles) on [0, 1]²: the same
// surface as a B-spline, exactly.
BSplineSurface bezierAsBSpline(int n, int m, const std::vector<Eigen::Vector3d>& net);

}  // namespace pdesurf
