// Mean and Gaussian curvature from analytic derivatives (docs/analysis.md):
//   E = X_u·X_u, F = X_u·X_v, G = X_v·X_v, n = X_u × X_v / |X_u × X_v|,
//   L = X_uu·n, M = X_uv·n, N = X_vv·n, EG − F² = |X_u × X_v|²,
//   K = (LN − M²) / (EG − F²),  H = (EN − 2FM + GL) / (2 (EG − F²)).
// H is signed with respect to n (a sphere with outward n has H = −1/R). One point here; a
// whole grid row at once in surface/row_frame.hpp.
#pragma once
#include <Eigen/Core>


namespace pdesurf {

struct Curvature {
  double H = 0.0, K = 0.0;
  bool regular = false;  // false where |X_u × X_v| vanishes (poles, zero speed): H = K = 0
};

Curvature curvatureAt(const Eigen::Vector3d& Xu, const Eigen::Vector3d& Xv, const Eigen::Vector3d& Xuu,
                      const Eigen::Vector3d& Xuv, const Eigen::Vector3d& Xvv);

}  // namespace pdesurf
