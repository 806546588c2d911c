// The surface a fill's loop lies in, for the fill's centre (scene/fill_conditions.cpp): a cubic
// height h(ξ, η) = c0 + c1 ξ + c2 η + c3 ξ² + c4 ξη + c5 η² + c6 ξ³ + c7 ξ²η + c8 ξη² + c9 η³
// over the plane through `origin` normal to n, fitted by least squares to the loop's points
// and to the slopes of the borders' tangent planes along it. A hole cut in a sheet that is a
// cubic height over that plane gets the sheet back exactly at the centre: its point, its
// tangent plane and (curvature fills) its curvature there.
#pragma once
#include <Eigen/Core>
#include <array>
#include <vector>

namespace pdesurf {

struct LoopSheet {
  bool fitted = false;         // false: the borders are too steep over the plane, or no cubic fits
  Eigen::Vector3d e1 = Eigen::Vector3d::Zero(), e2 = Eigen::Vector3d::Zero();  // the plane's axes (ξ, η)
  std::array<double, 10> c{};  // h's coefficients, in that order
  double residual = 0.0;       // RMS misfit of the loop's points, scene units
};

// x: the loop's points; t, d: the borders' tangents and cross derivatives there (the tangent
// plane); radius: the loop's mean radius.
LoopSheet fitLoopSheet(const std::vector<Eigen::Vector3d>& x, const std::vector<Eigen::Vector3d>& t, const std::vector<Eigen::Vector3d>& d,
                       const Eigen::Vector3d& origin, const Eigen::Vector3d& n, double radius);

}  // namespace pdesurf
