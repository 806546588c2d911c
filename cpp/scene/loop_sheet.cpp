#include "scene/loop_sheet.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace pdesurf {

namespace {

constexpr double kSteep = 0.3;          // |N·n| below this: a border too steep to give a slope
constexpr double kSlopeShare = 0.75;    // at least this share of the points must give one
constexpr double kMisfit = 0.02;        // of the radius: a loop no quadric follows better is not fitted

}  // namespace

LoopSheet fitLoopSheet(const std::vector<Eigen::Vector3d>& x, const std::vector<Eigen::Vector3d>& t, const std::vector<Eigen::Vector3d>& d,
                       const Eigen::Vector3d& origin, const Eigen::Vector3d& n, double radius) {
  LoopSheet s;
  s.e1 = n.unitOrthogonal();
  s.e2 = n.cross(s.e1);
  const size_t m = x.size();
  // Rows: a point's height (unit weight), and where the tangent plane is not steep its two
  // slopes times the radius (so that both kinds of row are lengths).
  Eigen::MatrixXd A(3 * m, 10);
  Eigen::VectorXd rhs(3 * m);
  size_t rows = 0, slopes = 0;
  for (size_t i = 0; i < m; ++i) {
    const Eigen::Vector3d p = x[i] - origin;
    const double xi = p.dot(s.e1), eta = p.dot(s.e2);
    A.row(rows) << 1, xi, eta, xi * xi, xi * eta, eta * eta, xi * xi * xi, xi * xi * eta, xi * eta * eta, eta * eta * eta;
    rhs(rows++) = p.dot(n);
    const Eigen::Vector3d N = t[i].cross(d[i]);
    const double along = N.dot(n);
    if (!(std::abs(along) >= kSteep * N.norm())) continue;
    ++slopes;
    A.row(rows) << 0, 1, 0, 2 * xi, eta, 0, 3 * xi * xi, 2 * xi * eta, eta * eta, 0;
    A.row(rows) *= radius;
    rhs(rows++) = -N.dot(s.e1) / along * radius;
    A.row(rows) << 0, 0, 1, 0, xi, 2 * eta, 0, xi * xi, 2 * xi * eta, 3 * eta * eta;
    A.row(rows) *= radius;
    rhs(rows++) = -N.dot(s.e2) / along * radius;
  }
  if (m == 0 || slopes < kSlopeShare * m) return s;
  const Eigen::VectorXd c = A.topRows(rows).colPivHouseholderQr().solve(rhs.head(rows));
  if (!c.allFinite()) return s;
  double misfit = 0.0;
  for (size_t i = 0; i < m; ++i) {
    const Eigen::Vector3d p = x[i] - origin;
    const double xi = p.dot(s.e1), eta = p.dot(s.e2);
    const double h = c(0) + c(1) * xi + c(2) * eta + c(3) * xi * xi + c(4) * xi * eta + c(5) * eta * eta + c(6) * xi * xi * xi +
                     c(7) * xi * xi * eta + c(8) * xi * eta * eta + c(9) * eta * eta * eta;
    misfit += (h - p.dot(n)) * (h - p.dot(n));
  }
  s.residual = std::sqrt(misfit / static_cast<double>(m));
  for (int k = 0; k < 10; ++k) s.c[k] = c(k);
  s.fitted = s.residual <= kMisfit * radius;
  return s;
}

}  // namespace pdesurf
