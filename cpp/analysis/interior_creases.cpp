#include "analysis/interior_creases.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "surface/mesh.hpp"

namespace pdesurf {

namespace {

struct Largest {
  double deg = 0.0, u = 0.0, v = 0.0;
};

// The largest angle between neighbouring unit normals on an n × n grid of the margins' range.
// Points without a tangent plane (|X_u × X_v| at rounding of |X_u||X_v|) are skipped.
Largest largestTurn(const SeparableSurface& surface, int n, double marginFraction, bool sharpSeam) {
  SeparableSurface s = surface;  // the factors are functions of absolute u, v: only the range changes
  const double margin = marginFraction * (surface.u1 - surface.u0);
  s.u0 = surface.u0 + margin, s.u1 = surface.u1 - margin;
  if (sharpSeam) {
    const double vMargin = marginFraction * (surface.v1 - surface.v0);
    s.v0 = surface.v0 + vMargin, s.v1 = surface.v1 - vMargin;
  }
  const GridSamples g = sampleGrid(s, n, n);
  const size_t m = static_cast<size_t>(n) + 1;
  std::vector<Eigen::Vector3d> normal(m * m);
  std::vector<char> defined(m * m, 0);
  for (size_t k = 0; k < m * m; ++k) {
    const Eigen::Vector3d Xu(&g.Xu[3 * k]), Xv(&g.Xv[3 * k]);
    const Eigen::Vector3d c = Xu.cross(Xv);
    if (c.norm() > 1e-12 * Xu.norm() * Xv.norm()) normal[k] = c.normalized(), defined[k] = 1;
  }
  Largest out;
  const auto turn = [&](size_t a, size_t b) {
    if (!defined[a] || !defined[b]) return;
    const double deg = std::atan2(normal[a].cross(normal[b]).norm(), normal[a].dot(normal[b])) * 180.0 / M_PI;
    if (deg > out.deg) out = {deg, g.u[a % m], g.v[a / m]};
  };
  for (size_t j = 0; j < m; ++j)
    for (size_t i = 0; i < m; ++i) {
      if (i + 1 < m) turn(j * m + i, j * m + i + 1);
      if (j + 1 < m) turn(j * m + i, (j + 1) * m + i);
    }
  return out;
}

}  // namespace

InteriorCreases measureCreases(const std::string& name, const SeparableSurface& s, int n, double margin, bool sharpSeam) {
  InteriorCreases r;
  r.patch = name;
  const Largest coarse = largestTurn(s, n, margin, sharpSeam), fine = largestTurn(s, 2 * n, margin, sharpSeam);
  r.coarseDeg = coarse.deg, r.fineDeg = fine.deg;
  r.creaseDeg = std::max(0.0, 2 * fine.deg - coarse.deg);
  r.u = fine.u, r.v = fine.v;
  r.ok = r.creaseDeg <= kCreaseToleranceDeg;
  return r;
}

}  // namespace pdesurf
