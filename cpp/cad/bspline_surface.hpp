// A non-rational tensor-product B-spline surface, the form pdesurf hands to CAD (STEP, IGES,
// 3dm). Clamped knot vectors in the patch's own parameters, so a face's (u, v) is the patch's
// (u, v) and a reader can compare pointwise. A surface closed in v (a blend between closed
// borders, a fill) is periodic in the fit and written clamped at the seam: its first and last
// pole columns coincide and it stays C^(degreeV-1) across the seam.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

namespace pdesurf {

// Bézier patches go out as they are, up to degree 16.
constexpr int kMaxBSplineDegree = 16;

struct BSplineSurface {
  std::string name;
  int degreeU = 3, degreeV = 3;
  // Full knot vectors, clamped (end knots repeated degree + 1 times):
  // knotsU.size() == countU + degreeU + 1, knotsV.size() == countV + degreeV + 1.
  std::vector<double> knotsU, knotsV;
  int countU = 0, countV = 0;
  std::vector<Eigen::Vector3d> poles;  // poles[i * countV + j]: i along u, j along v
  bool closedV = false;                // the v = v0 and v = v1 borders coincide (seam)
  // A border collapsed to a point (a fill's centre, a cone's apex), kBezierEdge order u0 u1 v0 v1.
  bool degenerate[4] = {false, false, false, false};

  const Eigen::Vector3d& pole(int i, int j) const { return poles[size_t(i) * countV + j]; }
  Eigen::Vector3d& pole(int i, int j) { return poles[size_t(i) * countV + j]; }
  double u0() const { return knotsU.front(); }
  double u1() const { return knotsU.back(); }
  double v0() const { return knotsV.front(); }
  double v1() const { return knotsV.back(); }
};

// The knot span index i with knots[i] <= t < knots[i + 1] (the last non-empty span at t = end).
int findSpan(const std::vector<double>& knots, int degree, int count, double t);
// ders[k * (degree + 1) + r] = k-th derivative of N_{span - degree + r} at t, k = 0..maxDerivative
// (The NURBS Book, A2.3).
void basisDerivatives(const std::vector<double>& knots, int degree, int span, double t, int maxDerivative,
                      double* ders);
// ∂^{du+dv} S / ∂u^du ∂v^dv at (u, v).
Eigen::Vector3d evaluate(const BSplineSurface& s, double u, double v, int du = 0, int dv = 0);
// Structural checks (sizes, clamped non-decreasing knots, finite poles); false with a reason.
bool wellFormed(const BSplineSurface& s, std::string* why = nullptr);

}  // namespace pdesurf
