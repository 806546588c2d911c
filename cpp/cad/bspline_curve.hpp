// A B-spline curve in 3D: a face's border as its pole row (clamped knots), and an exact part of
// it by knot insertion, the form a shared edge's curve takes in STEP and IGES.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "cad/bspline_surface.hpp"

namespace pdesurf {

struct BSplineCurve {
  int degree = 3;
  std::vector<double> knots;  // clamped, poles.size() + degree + 1
  std::vector<Eigen::Vector3d> poles;
};

// The border of s in kBezierEdge's order (u0, u1 run along v; v0, v1 along u), in s's own
// parameter: a surface's border is the curve of its outer pole row.
BSplineCurve borderCurve(const BSplineSurface& s, int border);

// The part over [a, b] (a < b, inside the curve's range), exactly: a and b inserted as knots to
// full multiplicity (Boehm), the poles between kept.
BSplineCurve subCurve(const BSplineCurve& c, double a, double b);

Eigen::Vector3d evaluate(const BSplineCurve& c, double t);

}  // namespace pdesurf
