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
  // The formulas of curvatureAt, in scalars over structure-of-arrays rows: no temporaries per
  // vertex, one square root and one division.
  const size_t m = row.d[0][0].size();
  const double *xu = row.at(1, 0), *yu = row.at(1, 1), *zu = row.at(1, 2);
  const double *xv = row.at(2, 0), *yv = row.at(2, 1), *zv = row.at(2, 2);
  const double *xuu = row.at(3, 0), *yuu = row.at(3, 1), *zuu = row.at(3, 2);
  const double *xuv = row.at(4, 0), *yuv = row.at(4, 1), *zuv = row.at(4, 2);
  const double *xvv = row.at(5, 0), *yvv = row.at(5, 1), *zvv = row.at(5, 2);
  int degenerate = 0;
  for (size_t i = 0; i < m; ++i) {
    const double nx = yu[i] * zv[i] - zu[i] * yv[i], ny = zu[i] * xv[i] - xu[i] * zv[i], nz = xu[i] * yv[i] - yu[i] * xv[i];
    const double det = nx * nx + ny * ny + nz * nz;
    const double E = xu[i] * xu[i] + yu[i] * yu[i] + zu[i] * zu[i], G = xv[i] * xv[i] + yv[i] * yv[i] + zv[i] * zv[i];
    const double big = std::max(E, G);
    double h = 0.0, k = 0.0;
    if (det > 1e-24 * big * big) {
      const double F = xu[i] * xv[i] + yu[i] * yv[i] + zu[i] * zv[i];
      const double inv = 1.0 / std::sqrt(det);  // n = (nx, ny, nz) · inv
      const double L = (xuu[i] * nx + yuu[i] * ny + zuu[i] * nz) * inv;
      const double M = (xuv[i] * nx + yuv[i] * ny + zuv[i] * nz) * inv;
      const double N = (xvv[i] * nx + yvv[i] * ny + zvv[i] * nz) * inv;
      const double invDet = 1.0 / det;
      k = (L * N - M * M) * invDet;
      h = 0.5 * (E * N - 2 * F * M + G * L) * invDet;
    } else {
      ++degenerate;
    }
    // float output: clamp what float cannot hold (a near-cusp) instead of writing ±inf.
    H[i] = static_cast<float>(std::clamp(h, -3e38, 3e38));
    K[i] = static_cast<float>(std::clamp(k, -3e38, 3e38));
  }
  return degenerate;
}

}  // namespace pdesurf
