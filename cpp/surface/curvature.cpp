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

int curvatureRow(const GridRow& row, float* H, float* K) {
  const size_t m = row.d[0][0].size();
  int degenerate = 0;
  for (size_t i = 0; i < m; ++i) {
    Eigen::Vector3d d[6];
    for (int q = 0; q < 6; ++q) d[q] = {row.d[q][0][i], row.d[q][1][i], row.d[q][2][i]};
    const Curvature k = curvatureAt(d[1], d[2], d[3], d[4], d[5]);
    degenerate += !k.regular;
    // float output: clamp what float cannot hold (a near-cusp) instead of writing ±inf.
    H[i] = static_cast<float>(std::clamp(k.H, -3e38, 3e38));
    K[i] = static_cast<float>(std::clamp(k.K, -3e38, 3e38));
  }
  return degenerate;
}

}  // namespace pdesurf
