// Seed 002's variational Bézier surfaces: the limits that must hold.
#include <doctest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "bezier/bernstein.hpp"
#include "bezier/bezier_solver.hpp"
#include "bezier/bezier_solver_cache.hpp"
#include "common/errors.hpp"

using namespace pdesurf;

namespace {

// The Bernstein control net of a polynomial surface f of degree <= n×m (interpolation at a
// uniform grid is exact for it).
ControlNet netOf(int n, int m, const std::function<Eigen::Vector3d(double, double)>& f) {
  Eigen::MatrixXd Bu(n + 1, n + 1), Bv(m + 1, m + 1);
  for (int r = 0; r <= n; ++r) {
    const auto b = bernstein(n, static_cast<double>(r) / n);
    for (int i = 0; i <= n; ++i) Bu(r, i) = b[i];
  }
  for (int r = 0; r <= m; ++r) {
    const auto b = bernstein(m, static_cast<double>(r) / m);
    for (int j = 0; j <= m; ++j) Bv(r, j) = b[j];
  }
  ControlNet net((n + 1) * (m + 1));
  for (int c = 0; c < 3; ++c) {
    Eigen::MatrixXd X(n + 1, m + 1);
    for (int r = 0; r <= n; ++r)
      for (int s = 0; s <= m; ++s) X(r, s) = f(static_cast<double>(r) / n, static_cast<double>(s) / m)(c);
    const Eigen::MatrixXd P = Bu.fullPivLu().solve(Bv.fullPivLu().solve(X.transpose()).transpose());
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= m; ++j) net[i * (m + 1) + j](c) = P(i, j);
  }
  return net;
}

BezierProblem problem(int n, int m, BezierEnergy e, const ControlNet& s, double lambda = 0, double gamma = 0) {
  BezierProblem p;
  p.n = n, p.m = m, p.energy = e, p.initial = s, p.lambda = lambda, p.gamma = gamma;
  p.normals.n1 = p.normals.m1 = 1;
  p.normals.vectors = {{0, 0, 1}, {0.3, 0, 1}, {0, 0.3, 1}, {0.3, 0.3, 1}};
  return p;
}

ControlNet bumpy(int n, int m) {
  return netOf(n, m, [](double u, double v) {
    return Eigen::Vector3d(u + 0.1 * v * v, v, 0.4 * std::sin(3 * u) * std::cos(2 * v) + 0.2 * u * v);
  });
}

double maxDiff(const ControlNet& a, const ControlNet& b) {
  double d = 0;
  for (size_t k = 0; k < a.size(); ++k) d = std::max(d, (a[k] - b[k]).norm());
  return d;
}

}  // namespace

TEST_CASE("bezier: with λ = γ = 0 a planar boundary gives a planar surface") {
  for (BezierEnergy e : {BezierEnergy::Membrane, BezierEnergy::ThinPlate}) {
    ControlNet s = bumpy(6, 7);
    for (auto& p : s) p.z() *= 1.0;
    ControlNet flat = s;
    for (int i = 0; i <= 6; ++i)
      for (int j = 0; j <= 7; ++j) {
        const BezierProblem probe = problem(6, 7, e, s);
        if (probe.isFixed(i, j)) flat[i * 8 + j].z() = 0.25;  // the boundary rings lie in z = 0.25
        else flat[i * 8 + j].z() = 3.0;                        // the interior starts far off it
      }
    const ControlNet r = solveBezier(problem(6, 7, e, flat));
    double worst = 0;
    for (const auto& p : r) worst = std::max(worst, std::abs(p.z() - 0.25));
    CHECK(worst < 1e-10);  // rounding times the thin-plate matrix's condition number
  }
}

TEST_CASE("bezier: a surface that already minimises the energy comes back unchanged") {
  // Harmonic (u, v, u² - v²) for the membrane; biharmonic (u, v, u² + v²) for the thin plate,
  // degree-elevated to 7×6; the interior starts perturbed.
  const ControlNet harmonic = netOf(7, 6, [](double u, double v) { return Eigen::Vector3d(u, v, u * u - v * v); });
  const ControlNet biharmonic = netOf(7, 6, [](double u, double v) { return Eigen::Vector3d(u, v, u * u + v * v); });
  for (auto [e, exact] : {std::pair{BezierEnergy::Membrane, harmonic}, std::pair{BezierEnergy::ThinPlate, biharmonic}}) {
    ControlNet start = exact;
    const BezierProblem p = problem(7, 6, e, start);
    for (int i = 0; i <= 7; ++i)
      for (int j = 0; j <= 6; ++j)
        if (!p.isFixed(i, j)) start[i * 7 + j] += Eigen::Vector3d(0.3, -0.2, 0.5);
    CHECK(maxDiff(solveBezier(problem(7, 6, e, start)), exact) < 1e-11);
  }
}

TEST_CASE("bezier: fixed control points are untouched bit for bit; the energy never exceeds S's or a perturbation's") {
  std::mt19937 rng(5);
  std::normal_distribution<double> N(0.0, 0.05);
  for (BezierEnergy e : {BezierEnergy::Membrane, BezierEnergy::ThinPlate})
    for (double lambda : {0.0, 10.0})
      for (double gamma : {0.0, 3.0}) {
        const ControlNet s = bumpy(8, 8);
        const BezierProblem p = problem(8, 8, e, s, lambda, gamma);
        const BezierSolver solver(p);
        const ControlNet r = solver.solve(s);
        for (int i = 0; i <= 8; ++i)
          for (int j = 0; j <= 8; ++j)
            if (p.isFixed(i, j)) REQUIRE((r[i * 9 + j].array() == s[i * 9 + j].array()).all());
        const double er = solver.energy(r, s);
        CHECK(er <= solver.energy(s, s) + 1e-12);
        for (int trial = 0; trial < 20; ++trial) {
          ControlNet q = r;
          for (int i = 0; i <= 8; ++i)
            for (int j = 0; j <= 8; ++j)
              if (!p.isFixed(i, j)) q[i * 9 + j] += Eigen::Vector3d(N(rng), N(rng), N(rng));
          CHECK(er < solver.energy(q, s));
        }
      }
}

TEST_CASE("bezier: as γ grows the result converges to S; as λ grows the normal misfit falls") {
  for (BezierEnergy e : {BezierEnergy::Membrane, BezierEnergy::ThinPlate}) {
    const ControlNet s = bumpy(8, 8);
    double last = INFINITY;
    for (double gamma : {1.0, 10.0, 100.0, 1e3, 1e4, 1e6, 1e8, 1e10}) {
      const double d = maxDiff(solveBezier(problem(8, 8, e, s, 0.0, gamma)), s);
      CHECK(d < last);
      last = d;
    }
    CHECK(last < 1e-5);
    last = INFINITY;
    for (double lambda : {0.0, 1.0, 10.0, 100.0, 1000.0}) {
      const BezierSolver solver(problem(8, 8, e, s, lambda, 0.0));
      const double misfit = solver.normalMisfit(solver.solve(s));
      CAPTURE(lambda);
      CHECK(misfit < last);
      last = misfit;
    }
  }
}

TEST_CASE("bezier: discrete normal fields (Eqs. 5-7) behave the same way") {
  const ControlNet s = bumpy(8, 8);
  BezierProblem p = problem(8, 8, BezierEnergy::Membrane, s);
  p.normals = {};
  p.normals.discrete = true;
  p.normals.np = p.normals.mp = 16;
  for (int i = 0; i <= 16; ++i)
    for (int j = 0; j <= 16; ++j) p.normals.vectors.push_back(Eigen::Vector3d(0.2 * (j - 8) / 8.0, 0, 1).normalized());
  double last = INFINITY;
  for (double lambda : {0.0, 1.0, 10.0, 50.0}) {
    p.lambda = lambda;
    const BezierSolver solver(p);
    const ControlNet r = solver.solve(s);
    CHECK(solver.normalMisfit(r) < last);
    last = solver.normalMisfit(r);
  }
  // Per-sample weights: zero weight everywhere equals λ = 0.
  p.lambda = 50;
  p.normals.lambdaWeight.assign(17 * 17, 0.0);
  BezierProblem q = p;
  q.lambda = 0;
  q.normals.lambdaWeight.clear();
  CHECK(maxDiff(solveBezier(p), solveBezier(q)) < 1e-12);
}

TEST_CASE("bezier: the factorisation is reused when only S changes") {
  const BezierProblem p = problem(8, 8, BezierEnergy::ThinPlate, bumpy(8, 8), 10.0, 2.0);
  const BezierSolver solver(p);
  ControlNet other = bumpy(8, 8);
  for (auto& q : other) q += Eigen::Vector3d(0.1, 0.2, -0.3);  // a drag of everything
  BezierProblem fresh = p;
  fresh.initial = other;
  CHECK(maxDiff(solver.solve(other), solveBezier(fresh)) < 1e-13);
}

TEST_CASE("bezier: bad input is a named error that says what to change") {
  auto message = [](BezierProblem p) {
    try {
      BezierSolver s(p);
    } catch (const Error& e) {
      return std::string(errorCodeName(e.code())) + ": " + e.what();
    }
    return std::string("ok");
  };
  CHECK(message(problem(1, 4, BezierEnergy::Membrane, bumpy(1, 4))).find("needs degree 2x2 or more") != std::string::npos);
  CHECK(message(problem(3, 6, BezierEnergy::ThinPlate, bumpy(3, 6))).find("needs degree 4x4 or more") != std::string::npos);
  CHECK(message(problem(4, 4, BezierEnergy::Membrane, bumpy(4, 4), -1.0)) == "InvalidField: lambda must be a finite number >= 0");
  CHECK(message(problem(4, 4, BezierEnergy::Membrane, bumpy(4, 4), 0.0, -2.0)) == "InvalidField: gamma must be a finite number >= 0");
  BezierProblem p = problem(4, 4, BezierEnergy::Membrane, bumpy(4, 4), 1.0);
  p.normals.vectors[2] = Eigen::Vector3d::Zero();
  CHECK(message(p) == "InvalidField: normal 2 has zero length");
  p.normals.vectors[2] = Eigen::Vector3d(NAN, 0, 1);
  CHECK(message(p) == "NonFinite: normal 2 is not finite");
  p = problem(8, 8, BezierEnergy::ThinPlate, bumpy(8, 8), 1e40);  // the fairness drowns below rounding
  CHECK(message(p).rfind("Singular: the energy has no unique minimiser", 0) == 0);
}

TEST_CASE("bezier: a discrete field keeps the control net regular (exact fairness)") {
  // A flat square with a straight border and λ = γ = 0: the net must stay the regular grid.
  const ControlNet flat = netOf(7, 7, [](double u, double v) { return Eigen::Vector3d(u, v, 0.0); });
  BezierProblem p = problem(7, 7, BezierEnergy::Membrane, flat);
  p.normals = {};
  p.normals.discrete = true;
  p.normals.np = p.normals.mp = 16;
  p.normals.vectors.assign(17 * 17, Eigen::Vector3d(0, 0, 1));
  CHECK(maxDiff(solveBezier(p), flat) < 1e-10);  // was 2.4 with Eq. 5's unit-weight fairness sum
}

TEST_CASE("bezier: the solver cache reuses a factorisation only for an identical shape") {
  BezierSolverCache cache;
  BezierProblem p = problem(6, 6, BezierEnergy::Membrane, bumpy(6, 6), 10.0, 1.0);
  const BezierSolver* first = &cache.get(p);
  p.initial[10].z() += 0.3;  // a drag of S: same matrix
  CHECK(&cache.get(p) == first);
  CHECK(maxDiff(cache.get(p).solve(p.initial), solveBezier(p)) < 1e-13);
  p.lambda = 11.0;  // a different matrix
  CHECK(&cache.get(p) != first);
}
