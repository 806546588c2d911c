// Analytic derivatives along one edge of a patch (internal to analysis/): at each sample the
// point, the derivative along the edge (s) and across it into the patch (w, with w = ±u so
// that +w points inside), and the second derivatives, all from one tabulation of the
// separable form.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "surface/separable_surface.hpp"

namespace pdesurf {

struct EdgePoint {
  Eigen::Vector3d X, s, w, ww, ss, sw;  // X, ∂s, ∂w, ∂²w, ∂²s, ∂s∂w
};

// One edge point from a surface's partials at it (any surface: the solved one, a fitted face).
inline EdgePoint edgePointFrom(bool alongU, int end, const Eigen::Vector3d& X, const Eigen::Vector3d& Xu, const Eigen::Vector3d& Xv,
                               const Eigen::Vector3d& Xuu, const Eigen::Vector3d& Xuv, const Eigen::Vector3d& Xvv) {
  const double sign = end == 0 ? 1.0 : -1.0;
  if (alongU) return {X, Xu, sign * Xv, Xvv, Xuu, sign * Xuv};
  return {X, Xv, sign * Xu, Xuu, Xvv, sign * Xuv};
}

// The edge u = end (alongU false: it runs along v over [a0, a1]) or v = end (alongU true: it
// runs along u over [a0, a1]) of `surface`, at `samples` evenly spaced points (both ends).
std::vector<EdgePoint> edgeSamples(const SeparableSurface& surface, bool alongU, int end, double a0, double a1, int samples);
// The same at the given parameters along the edge (point by point: for few, uneven samples).
std::vector<EdgePoint> edgeSamplesAt(const SeparableSurface& surface, bool alongU, int end, const std::vector<double>& at);

}  // namespace pdesurf
