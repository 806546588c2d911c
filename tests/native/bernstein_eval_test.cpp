// Bézier patches are drawn in Bernstein form: the sampled surface and its normals agree with a
// long-double de Casteljau evaluation of the same control net, for every degree up to the cap
// and for solved nets (γ up to 1e6) whose control points are in the thousands.
#include <doctest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "bezier/bezier_solver.hpp"
#include "common/errors.hpp"
#include "surface/mesh.hpp"
#include "test_util.hpp"

using namespace pdesurf;

namespace {

using Vec3L = Eigen::Matrix<long double, 3, 1>;

// de Casteljau in long double over points p[0..n] at t.
Vec3L casteljau(std::vector<Vec3L> p, long double t) {
  for (size_t r = 1; r < p.size(); ++r)
    for (size_t i = 0; i + r < p.size(); ++i) p[i] = (1 - t) * p[i] + t * p[i + 1];
  return p[0];
}

// ∂^{du+dv} R / ∂u^du ∂v^dv (du, dv ≤ 1) in long double: hodographs, then de Casteljau.
Vec3L reference(int n, int m, const ControlNet& net, long double u, long double v, int du, int dv) {
  std::vector<Vec3L> rows;
  for (int i = 0; i <= n; ++i) {
    std::vector<Vec3L> row;
    for (int j = 0; j <= m; ++j) row.push_back(net[i * (m + 1) + j].cast<long double>());
    if (dv) {
      for (int j = 0; j < m; ++j) row[j] = m * (row[j + 1] - row[j]);
      row.pop_back();
    }
    rows.push_back(casteljau(row, v));
  }
  if (du) {
    for (int i = 0; i < n; ++i) rows[i] = n * (rows[i + 1] - rows[i]);
    rows.pop_back();
  }
  return casteljau(rows, u);
}

struct Agreement {
  double position = 0.0;  // relative to the surface's size (bounding-box diagonal)
  double normalRad = 0.0;
  double absolute = 0.0, netMax = 0.0, size = 0.0;  // largest position error; largest |control point| coordinate; size
};

Agreement agreement(int n, int m, const ControlNet& net) {
  const SeparableSurface s = bezierToSeparable(n, m, net);
  const int N = 24;
  const GridSamples g = sampleGrid(s, N, N);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  double worst = 0.0, angle = 0.0;
  for (int j = 0; j <= N; ++j)
    for (int i = 0; i <= N; ++i) {
      const size_t k = 3 * (static_cast<size_t>(j) * (N + 1) + i);
      const long double u = g.u[i], v = g.v[j];
      const Eigen::Vector3d X = reference(n, m, net, u, v, 0, 0).cast<double>();
      lo = lo.cwiseMin(X), hi = hi.cwiseMax(X);
      worst = std::max(worst, (Eigen::Vector3d(&g.X[k]) - X).norm());
      const Vec3L nRef = reference(n, m, net, u, v, 1, 0).cross(reference(n, m, net, u, v, 0, 1));
      const Eigen::Vector3d nGot = Eigen::Vector3d(&g.Xu[k]).cross(Eigen::Vector3d(&g.Xv[k]));
      if (nRef.norm() == 0) continue;
      const double c = nGot.normalized().dot(nRef.normalized().cast<double>());
      const double sn = nGot.normalized().cross(nRef.normalized().cast<double>()).norm();
      angle = std::max(angle, std::atan2(sn, c));
    }
  double netMax = 0.0;
  for (const auto& q : net) netMax = std::max(netMax, q.cwiseAbs().maxCoeff());
  return {worst / (hi - lo).norm(), angle, worst, netMax, (hi - lo).norm()};
}

ControlNet randomNet(int n, int m, double magnitude, std::mt19937& rng) {
  std::uniform_real_distribution<double> d(-magnitude, magnitude);
  ControlNet net((n + 1) * (m + 1));
  for (auto& p : net) p = {d(rng), d(rng), d(rng)};
  return net;
}

}  // namespace

TEST_CASE("bernstein evaluation: random nets of magnitude 1e4, degrees 1-16, match long-double de Casteljau") {
  std::mt19937 rng(8);
  Agreement worst;
  // Every degree natively; under AddressSanitizer and in wasm a spread of them.
  const int step = testing::kSlowLongDouble ? 3 : 1;
  for (int n = 1; n <= 16; n += step)  // 1, 4, …, 16 there
    for (int m : {1, n, 16}) {
      CAPTURE(n);
      CAPTURE(m);
      const Agreement a = agreement(n, m, randomNet(n, m, 1e4, rng));
      CHECK(a.position < 1e-12);
      CHECK(a.normalRad < 1e-9);
      worst.position = std::max(worst.position, a.position), worst.normalRad = std::max(worst.normalRad, a.normalRad);
    }
  MESSAGE("random nets: position " << worst.position << " of the size, normals " << worst.normalRad << " rad");
}

TEST_CASE("bernstein evaluation: solved nets (γ up to 1e6, initial nets of magnitude 1e4) match long-double de Casteljau") {
  std::mt19937 rng(80);
  Agreement worst;
  double largestNet = 0.0;
  int refused = 0;
  const std::vector<int> degrees = testing::kSlowLongDouble ? std::vector<int>{4, 10, 16} : std::vector<int>{4, 7, 10, 12, 14, 16};
  for (int n : degrees)
    for (double gamma : {1.0, 1e3, 1e6})
      for (BezierEnergy e : {BezierEnergy::Membrane, BezierEnergy::ThinPlate}) {
        BezierProblem p;
        p.n = p.m = n, p.energy = e, p.initial = randomNet(n, n, 1e4, rng), p.lambda = 3.0, p.gamma = gamma;
        p.normals.n1 = p.normals.m1 = 1;
        p.normals.vectors = {{0, 0, 1}, {0.3, 0, 1}, {0, 0.3, 1}, {0.3, 0.3, 1}};
        ControlNet net;
        try {
          net = solveBezier(p);
        } catch (const Error& e) {  // a named refusal of a near-singular system is allowed, not a wrong surface
          CHECK(e.code() == ErrorCode::Singular);
          ++refused;
          continue;
        }
        for (const auto& q : net) largestNet = std::max(largestNet, q.cwiseAbs().maxCoeff());
        CAPTURE(n);
        CAPTURE(gamma);
        const Agreement a = agreement(n, n, net);
        // Nets of 1e4 give 1e-12 of the size; where the solve spreads a net to 1e9 around a
        // surface of 1e4, no double evaluation can beat Bernstein form's backward error bound,
        // (n + 1)·eps·max|P| (monomials lose 1e-3 of the size and more, see the next case).
        CHECK(a.absolute <= std::max(1e-12 * a.size, (n + 1) * 2.3e-16 * a.netMax));
        CHECK(a.normalRad < 1e-9);
        worst.position = std::max(worst.position, a.position), worst.normalRad = std::max(worst.normalRad, a.normalRad);
      }
  CHECK(refused == 0);  // of 36 problems; up to 3 were refused before the interior-basis fallback (issue 17)
  MESSAGE("solved nets (" << refused << " refused as singular; largest control point " << largestNet << "): position " << worst.position << " of the size, normals "
                                               << worst.normalRad << " rad");
}

TEST_CASE("bernstein evaluation: a net in the thousands whose surface stays within 1 is drawn where it is") {
  // Σ_i (−1)^i C B_i^n(u) = C (1 − 2u)^n: alternating control points of size C = 5000 with a
  // surface below C·2^-n in the middle. Monomial coefficients cancel catastrophically here.
  const int n = 16;
  ControlNet net((n + 1) * (n + 1));
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) net[i * (n + 1) + j] = {static_cast<double>(j) / n, static_cast<double>(i) / n, (i % 2 ? -5000.0 : 5000.0)};
  const SeparableSurface s = bezierToSeparable(n, n, net);
  for (double u : {0.3, 0.45, 0.5, 0.6, 0.77}) {
    const double exact = 5000.0 * std::pow(1 - 2 * u, n);
    CHECK(std::abs(evalPoint(s, u, 0.4)(2) - exact) < 1e-11);  // 2e-15 of the net's size
    CHECK(std::abs(evalPoint(s, u, 0.4, 1, 0)(2) - (-2.0 * n * 5000.0 * std::pow(1 - 2 * u, n - 1))) < 1e-9);
  }
}
