#include "surface/curvature.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace pdesurf {

Curvature curvatureAt(const Eigen::Vector3d& Xu, const Eigen::Vector3d& Xv, const Eigen::Vector3d& Xuu,
                      const Eigen::Vector3d& Xuv, const Eigen::Vector3d& Xvv) {
  const Eigen::Vector3d cross = Xu.cross(Xv);
  const double det = cross.squaredNorm();  // EG − F²
  Curvature k;
  // A pole: the cross product vanishes against the larger speed (sin t = 1e-16 at t = π
  // leaves X_v = 1e-16 R, not 0: its curvature would divide rounding by rounding).
  const double big = std::max(Xu.squaredNorm(), Xv.squaredNorm());
  if (!(det > 1e-24 * big * big)) return k;
  const Eigen::Vector3d n = cross / std::sqrt(det);
  const double E = Xu.squaredNorm(), F = Xu.dot(Xv), G = Xv.squaredNorm();
  const double L = Xuu.dot(n), M = Xuv.dot(n), N = Xvv.dot(n);
  k.K = (L * N - M * M) / det;
  k.H = (E * N - 2 * F * M + G * L) / (2 * det);
  k.regular = std::isfinite(k.H) && std::isfinite(k.K);
  if (!k.regular) k.H = k.K = 0.0;
  return k;
}

}  // namespace pdesurf
