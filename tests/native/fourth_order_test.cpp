// The fourth-order closed form of seed 000 (Eqs. 2-8), including the complex-root case the
// paper's appendix calls unsolvable. Each check compares against something independent.
#include <doctest.h>

#include <Eigen/Dense>
#include <cmath>

#include "common/errors.hpp"
#include "ode/even_ode.hpp"
#include "pde/closed_form.hpp"
#include "random_problem.hpp"
#include "test_util.hpp"

using namespace pdesurf;
using namespace pdesurf::testing;


TEST_CASE("fourth order: boundary conditions and PDE residual for random mixtures in every root regime") {
  std::mt19937 rng(20261122);
  for (Regime regime : {Regime::RealDistinct, Regime::Repeated, Regime::Complex}) {
    for (int trial = 0; trial < 40; ++trial) {
      const PdeProblem p = randomProblem(fourthOrderAlpha(regime, rng), rng);
      const SeparableSurface s = solveClosedForm(p);
      CAPTURE(static_cast<int>(regime));
      CAPTURE(trial);
      CHECK(boundaryError(p, s) < 1e-10);
      CHECK(pdeResidual(p, s) < 1e-9);
    }
  }
}

TEST_CASE("fourth order: Bloor-Wilson per-mode form for b=1, c=2a^2, d=a^4") {
  // (∂²u + a²∂²v)² X = 0 with cos(nv) data: G = (c1 + c2 u) e^{anu} + (c3 + c4 u) e^{-anu}.
  for (double a : {0.5, 1.0, 3.0}) {
    for (int n : {1, 2, 5}) {
      const double g0 = 0.7, g0u = -1.3, g1 = 1.1, g1u = 0.4;
      PdeProblem p;
      p.v1 = 2 * M_PI;
      for (auto& c : p.component) {
        c.alpha = {1.0, 2 * a * a, std::pow(a, 4)};
        VFunction f{Family::Cos, static_cast<double>(n), 0};
        c.left = {{{f, g0}}, {{f, g0u}}};
        c.right = {{{f, g1}}, {{f, g1u}}};
      }
      const SeparableSurface s = solveClosedForm(p);
      const double k = a * n;
      auto basis = [&](double u, int der) {
        // value or first derivative of the four Bloor-Wilson functions
        const double ep = std::exp(k * u), em = std::exp(-k * u);
        if (der == 0) return Eigen::Vector4d(ep, u * ep, em, u * em);
        return Eigen::Vector4d(k * ep, (1 + k * u) * ep, -k * em, (1 - k * u) * em);
      };
      Eigen::Matrix4d m;
      m.row(0) = basis(0, 0);
      m.row(1) = basis(0, 1);
      m.row(2) = basis(1, 0);
      m.row(3) = basis(1, 1);
      const Eigen::Vector4d coef = m.fullPivLu().solve(Eigen::Vector4d(g0, g0u, g1, g1u));
      for (double u : {0.0, 0.13, 0.5, 0.77, 1.0}) {
        const double want = coef.dot(basis(u, 0)) * std::cos(n * 0.3);
        CHECK(evalComponent(s, 0, u, 0.3) == doctest::Approx(want).epsilon(1e-11));
      }
    }
  }
}

TEST_CASE("fourth order: large roots stay finite and accurate (a = 20, cos(30 v))") {
  const double a = 20, w = 30, k = a * w;  // double root r = ±600: e^{600} would overflow unscaled terms
  PdeProblem p;
  p.v1 = 2 * M_PI;
  for (auto& c : p.component) {
    c.alpha = {1.0, 2 * a * a, std::pow(a, 4)};
    VFunction f{Family::Cos, w, 0};
    c.left = {{{f, 1.0}}, {{f, 2.0}}};
    c.right = {{{f, -0.5}}, {{f, 3.0}}};
  }
  const SeparableSurface s = solveClosedForm(p);
  // Independent form with the growing exponential written about u = 1:
  // G = (c1 + c2 u) e^{-ku} + (c3 + c4 (u-1)) e^{k(u-1)}.
  auto basis = [&](double u, int der) {
    const double em = std::exp(-k * u), ep = std::exp(k * (u - 1));
    if (der == 0) return Eigen::Vector4d(em, u * em, ep, (u - 1) * ep);
    return Eigen::Vector4d(-k * em, (1 - k * u) * em, k * ep, (1 + k * (u - 1)) * ep);
  };
  Eigen::Matrix4d m;
  m.row(0) = basis(0, 0);
  m.row(1) = basis(0, 1);
  m.row(2) = basis(1, 0);
  m.row(3) = basis(1, 1);
  const Eigen::Vector4d coef = m.fullPivLu().solve(Eigen::Vector4d(1.0, 2.0, -0.5, 3.0));
  for (double u : {0.0, 0.001, 0.01, 0.5, 0.99, 0.999, 1.0}) {
    const double got = evalComponent(s, 0, u, 0.0);
    const double want = coef.dot(basis(u, 0));
    REQUIRE(std::isfinite(got));
    CHECK(std::abs(got - want) <= 1e-10 * std::max(1.0, std::abs(want)));
  }
}

TEST_CASE("fourth order: b = 0 is a named error") {
  PdeProblem p;
  p.v1 = 1;
  for (auto& c : p.component) {
    c.alpha = {1.0, 2.0, 1.0};
    c.left = {{}, {}};
    c.right = {{}, {}};
  }
  p.component[1].alpha[0] = 0.0;
  p.component[1].left[0] = {{VFunction{Family::Cos, 1, 0}, 1.0}};
  try {
    solveClosedForm(p);
    FAIL("expected an error");
  } catch (const Error& e) {
    CHECK(e.code() == ErrorCode::DegenerateOperator);
    CHECK(std::string(e.what()).find("component y") != std::string::npos);
  }
}
