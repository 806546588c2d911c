// A face as the CAD topology sees it (cad/brep_topology.hpp): a fitted B-spline, or a solved
// surface itself (analysis/bodies.cpp); and its area and part of a closed shell's volume.
#pragma once
#include <Eigen/Core>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "cad/bspline_surface.hpp"

namespace pdesurf {

// A face as the topology sees it: its parameter box, seam and collapsed borders, its points and
// first derivatives; the fitted B-spline when there is one (edges then get curves), and the
// parameters where its quadrature cells break (knots, creases).
struct TopologyFace {
  std::string name;
  double u0 = 0, u1 = 1, v0 = 0, v1 = 1;
  bool closedV = false;
  bool degenerate[4] = {false, false, false, false};
  std::function<Eigen::Vector3d(double u, double v, int du, int dv)> eval;
  // Optional: the points of border b (0: u0, 1: u1, 2: v0, 3: v1) at the parameters ts along
  // it, all at once (a solved surface tabulates its border line once instead of point by point).
  std::function<std::vector<Eigen::Vector3d>(int b, const std::vector<double>& ts)> borderPoints;
  const BSplineSurface* spline = nullptr;
  std::vector<double> uCells, vCells;  // sorted breaks, ends included
  // Given when already known (a caller that integrates faster): faceArea and faceSignedVolume
  // return them instead of integrating eval.
  double area = NAN, signedVolume = NAN;
};
TopologyFace topologyFace(const BSplineSurface& s);

// Area of a face: ∫∫ |X_u × X_v| du dv, and its part of a closed shell's volume,
// (1/3) ∫∫ X · (X_u × X_v) du dv (Gauss-Legendre, 4 points a cell each way).
double faceArea(const TopologyFace& f);
double faceSignedVolume(const TopologyFace& f);

}  // namespace pdesurf
