// The certified B-spline fit (cpp/cad/): its building blocks against independent evaluation,
// and the certificate against dense random samples of random separable surfaces from every
// family the core makes (exponential-polynomial u-factors, every v-family, general
// functions with creases, pointwise parts; open and closed ranges, degrees 3 and 5).
#include <doctest.h>

#include <random>

#include "basis/general_function.hpp"
#include "cad/bspline_fit.hpp"
#include "cad/creases.hpp"
#include "cad/derivative_bounds.hpp"
#include "cad/knots.hpp"
#include "common/errors.hpp"
#include "expr/interval.hpp"
#include "expr/parse.hpp"
#include "test_util.hpp"

using namespace pdesurf;

namespace {

Expr parseV(const std::string& text, bool u = false) { return parseExpression(text, {}, AllowedVariables{true, u, "u"}); }

VFunction general(const std::string& text) {
  VFunction g;
  g.family = Family::General;
  g.general = std::make_shared<GeneralFunction>(text, parseV(text));
  return g;
}

// A random real u-factor: Re Σ e^{c(u-s)} P(u-s) with oscillating, growing and decaying rates.
UFactor randomUFactor(std::mt19937& rng) {
  std::uniform_real_distribution<double> C(-1.0, 1.0), R(-6.0, 6.0);
  UFactor G;
  const int pieces = 1 + int(rng() % 3);
  for (int k = 0; k < pieces; ++k) {
    ExpPoly e;
    e.rate = cplx(R(rng), (rng() % 2) ? R(rng) : 0.0);
    e.shift = e.rate.real() > 0 ? 1.0 : 0.0;
    for (int d = 0; d <= int(rng() % 3); ++d) e.poly.push_back(cplx(C(rng), C(rng)));
    G.pieces.push_back(e);
  }
  return G;
}

VFunction randomVFunction(std::mt19937& rng, bool closed) {
  std::uniform_real_distribution<double> W(0.3, 3.0);
  static const char* generals[] = {"sin(v)*exp(0.3*cos(v))", "1/(2 + cos(v))", "abs(sin(v))", "cos(2*v)^3 + sin(v)",
                                   "sqrt(1.5 + sin(v))", "atan(cos(v))"};
  const int pick = int(rng() % 6);
  VFunction g;
  switch (pick) {
    case 0: g.family = Family::Cos, g.w = closed ? double(1 + rng() % 4) : W(rng); break;
    case 1: g.family = Family::Sin, g.w = closed ? double(1 + rng() % 4) : W(rng); break;
    case 2:
      if (closed) return general(generals[rng() % 6]);
      g.family = Family::Poly, g.n = int(rng() % 4); break;
    case 3:
      if (closed) return general(generals[rng() % 6]);
      g.family = (rng() % 2) ? Family::Exp : Family::Cosh, g.w = W(rng) / 3; break;
    default: return general(generals[rng() % 6]);
  }
  return g;
}

SeparableSurface randomSurface(std::mt19937& rng, bool closed, bool pointwise) {
  SeparableSurface s;
  s.u0 = 0, s.u1 = 1;
  s.v0 = 0, s.v1 = closed ? 2 * M_PI : 1.5;
  // A ring-like base keeps the surface regular; random terms on top.
  s.component[0].push_back({VFunction{Family::Cos, 1.0}, UFactor::polynomial({1.0, 0.5})});
  s.component[1].push_back({VFunction{Family::Sin, 1.0}, UFactor::polynomial({1.0, 0.5})});
  s.component[2].push_back({VFunction{}, UFactor::polynomial({0.0, 1.0})});
  std::uniform_real_distribution<double> A(-0.15, 0.15);
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 2; ++k) {
      UFactor G = randomUFactor(rng);
      // Scale the factor so each term stays a modest perturbation.
      double peak = 0;
      for (int i = 0; i <= 20; ++i) peak = std::max(peak, std::abs(G.eval(i / 20.0)));
      for (auto& piece : G.pieces)
        for (auto& p : piece.poly) p *= A(rng) / std::max(peak, 1e-9);
      s.component[size_t(c)].push_back({randomVFunction(rng, closed), G});
    }
  if (pointwise) s.pointwise[2] = parseV("0.05*sin(3*u + v)*cos(u*v)", true);
  return s;
}

}  // namespace

TEST_CASE("B-spline basis: partition of unity, derivatives against finite differences; knot insertion and clamping keep the curve") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(0, 1);
  for (int p : {3, 5}) {
    const std::vector<double> breaks{0, 0.1, 0.35, 0.4, 0.8, 1};
    const auto knots = clampedKnots(breaks, p);
    for (int trial = 0; trial < 20; ++trial) {
      const double t = U(rng);
      const auto n0 = collocation(knots, p, {t}, 0), n1 = collocation(knots, p, {t}, 1);
      CHECK(Eigen::MatrixXd(n0).sum() == doctest::Approx(1.0).epsilon(1e-14));
      const double h = 1e-6;
      const auto a = collocation(knots, p, {std::min(t + h, 1.0)}, 0), b = collocation(knots, p, {std::max(t - h, 0.0)}, 0);
      const double span = std::min(t + h, 1.0) - std::max(t - h, 0.0);
      CHECK((Eigen::MatrixXd(a - b) / span - Eigen::MatrixXd(n1)).cwiseAbs().maxCoeff() < 1e-5);
    }
    // A periodic curve and its clamped form agree everywhere; the clamped form is closed.
    Eigen::MatrixXd periodic = Eigen::MatrixXd::Random(int(breaks.size()) - 1 + 3, 3);
    const std::vector<double> pb{0, 0.7, 1.9, 2.5, 3.3, 4.4, 5.2, 2 * M_PI};
    periodic.resize(int(pb.size()) - 1, 3);
    periodic.setRandom();
    std::vector<double> ck;
    Eigen::MatrixXd cp;
    periodicToClamped(pb, p, periodic, &ck, &cp);
    CHECK((cp.row(0) - cp.row(cp.rows() - 1)).norm() == 0.0);
    const auto pk = periodicKnots(pb, p);
    double worst = 0;
    for (int i = 0; i <= 200; ++i) {
      const double t = 2 * M_PI * i / 200;
      const Eigen::MatrixXd a = collocation(pk, p, {t}, 0, int(pb.size()) - 1) * periodic;
      const Eigen::MatrixXd b = collocation(ck, p, {t}, 0) * cp;
      worst = std::max(worst, (a - b).cwiseAbs().maxCoeff());
    }
    CHECK(worst < 1e-13);
  }
}

TEST_CASE("interval arithmetic encloses every sampled value of random expressions; a pole gives the whole line") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> L(-3, 3), W(0.01, 2);
  const char* texts[] = {"sin(3*v)*exp(v) - v^3", "cos(v)^2/(1.5 + sin(v))", "atan(v)*sqrt(4 + v) + cosh(v)",
                         "abs(v - 0.3)*log(5 + v)", "tanh(v)*sinh(v) - v^-2", "asin(v/4) + acos(v/5)",
                         "exp(-v^2)*sign(v)", "(v + 1)^2.5 - 2^v"};
  for (const char* text : texts) {
    const Expr e = parseV(text);
    for (int trial = 0; trial < 50; ++trial) {
      const double a = L(rng), b = a + W(rng);
      const Interval vars[2] = {{a, b}, {0, 0}};
      const Interval r = enclose(e, vars);
      for (int k = 0; k <= 40; ++k) {
        const double v = k == 40 ? b : a + (b - a) * k / 40, at[2] = {v, 0};
        const double x = evaluate(*e, at);
        if (!std::isfinite(x)) continue;
        INFO(std::string(text), " on [", a, ", ", b, "] at ", v);
        CHECK((r.lo <= x && x <= r.hi));
        if (!(r.lo <= x && x <= r.hi)) MESSAGE(r.lo, " ", x, " ", r.hi);
      }
    }
  }
  const Interval around[2] = {{1.5, 1.7}, {0, 0}};
  CHECK_FALSE(enclose(parseV("tan(v)"), around).bounded());
  CHECK_FALSE(enclose(parseV("1/(v - 1.6)"), around).bounded());
}

TEST_CASE("derivative bounds hold at dense samples: random u-factors, every v-family, general functions") {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 40; ++trial) {
    const UFactor G = randomUFactor(rng);
    const VFunction g = randomVFunction(rng, trial % 2 == 0);
    for (int k : {0, 2, 4}) {
      const double a = (trial % 5) * 0.2, b = a + 0.2;
      const double bu = boundUFactor(G, k, a, b), bv = boundVFunction(g, k, a + 1, b + 1);
      for (int i = 0; i <= 50; ++i) {
        const double t = a + (b - a) * i / 50;
        CHECK(std::abs(G.eval(t, k)) <= bu);
        CHECK(std::abs(g.eval(t + 1, k)) <= bv * (1 + 1e-12) + 1e-12);
      }
    }
  }
}

TEST_CASE("creases: the zeros of abs and sign arguments inside the range, found to the last bits") {
  SeparableSurface s;
  s.v0 = 0, s.v1 = 2 * M_PI;
  s.component[0].push_back({general("abs(v - 1.25) + sign(cos(v))"), UFactor::polynomial({1.0})});
  const auto c = findCreases(s);
  REQUIRE(c.size() == 3);
  CHECK(c[0] == doctest::Approx(1.25).epsilon(1e-15));
  CHECK(c[1] == doctest::Approx(M_PI / 2).epsilon(1e-15));
  CHECK(c[2] == doctest::Approx(3 * M_PI / 2).epsilon(1e-15));
}

TEST_CASE("the fit's certificate holds: random surfaces, open and closed, degrees 3 and 5, dense random samples never exceed it") {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> U(0, 1);
  const int trials = testing::kTimeScale > 1 ? 4 : 16;
  for (int trial = 0; trial < trials; ++trial) {
    const bool closed = trial % 2 == 0, pointwise = trial % 4 == 3;
    const int degree = trial % 3 == 0 ? 3 : 5;
    const SeparableSurface s = randomSurface(rng, closed, pointwise);
    FitOptions o;
    o.degree = degree;
    o.tolerance = 1e-5;
    FitReport r;
    const BSplineSurface b = fitSurface(s, o, &r);
    INFO("trial ", trial, " closed ", closed, " degree ", degree, " poles ", b.countU, "x", b.countV);
    std::string why;
    REQUIRE(wellFormed(b, &why));
    CHECK(r.deviation <= o.tolerance);
    CHECK(r.sampledDeviation <= r.deviation);
    CHECK(r.normalDeviationDeg <= o.normalToleranceDeg);
    CHECK(b.u0() == s.u0);
    CHECK(b.v1() == s.v1);
    CHECK(b.closedV == closed);
    if (closed) CHECK((b.pole(1, 0) - b.pole(1, b.countV - 1)).norm() == 0.0);
    double worst = 0;
    for (int k = 0; k < 4000; ++k) {
      const double u = U(rng), v = s.v0 + (s.v1 - s.v0) * U(rng);
      worst = std::max(worst, (evalPoint(s, u, v) - evaluate(b, u, v)).norm());
    }
    CHECK(worst <= r.deviation);
    // The ends meet the surface's ends and tangent planes (Hermite rows): joins stay joins.
    // (Just inside the v-ends: a kink there, abs(sin(v)) at 0, has a normal on each side.)
    for (int k = 0; k <= 50; ++k) {
      const double v = s.v0 + (s.v1 - s.v0) * std::min(std::max(k / 50.0, 1e-9), 1 - 1e-9);
      for (double u : {s.u0, s.u1}) {
        CHECK((evalPoint(s, u, v) - evaluate(b, u, v)).norm() <= o.tolerance);
        const Eigen::Vector3d ns = evalPoint(s, u, v, 1, 0).cross(evalPoint(s, u, v, 0, 1)).normalized();
        const Eigen::Vector3d nb = evaluate(b, u, v, 1, 0).cross(evaluate(b, u, v, 0, 1)).normalized();
        CHECK(std::acos(std::min(1.0, ns.dot(nb))) * 180 / M_PI <= 0.01);
      }
    }
  }
}

TEST_CASE("a crease in v gets a knot of full multiplicity: the fit converges where a smooth spline could not") {
  SeparableSurface s;
  s.v0 = 0, s.v1 = 2;
  s.component[0].push_back({VFunction{Family::Poly, 1.0, 1}, UFactor::polynomial({1.0})});
  s.component[1].push_back({VFunction{}, UFactor::polynomial({0.0, 1.0})});
  s.component[2].push_back({general("abs(v - 0.7)*(1 + v)"), UFactor::polynomial({0.5, 0.5})});
  FitOptions o;
  o.tolerance = 1e-7;
  FitReport r;
  const BSplineSurface b = fitSurface(s, o, &r);
  CHECK(r.creases == 1);
  CHECK(r.deviation <= 1e-7);
  CHECK(b.countV < 40);
}

TEST_CASE("bad tolerances and unreachable ones are named errors") {
  std::mt19937 rng(5);
  const SeparableSurface s = randomSurface(rng, true, false);
  for (double bad : std::vector<double>{0.0, -1.0, NAN, INFINITY}) {
    FitOptions o;
    o.tolerance = bad;
    CHECK_THROWS_AS(fitSurface(s, o, nullptr), Error);
  }
  FitOptions o;
  o.tolerance = 1e-300;
  try {
    fitSurface(s, o, nullptr);
    FAIL("a tolerance of 1e-300 was reached");
  } catch (const Error& e) {
    CHECK(e.code() == ErrorCode::TooLarge);
    CHECK(std::string(e.what()).find("certified deviation of") != std::string::npos);
  }
  o.tolerance = 1e-4;
  o.degree = 4;
  CHECK_THROWS_AS(fitSurface(s, o, nullptr), Error);
}

TEST_CASE("a Bézier net is written exactly") {
  std::mt19937 rng(9);
  std::vector<Eigen::Vector3d> net;
  for (int k = 0; k < 4 * 6; ++k) net.push_back(Eigen::Vector3d::Random());
  const BSplineSurface b = bezierAsBSpline(3, 5, net);
  REQUIRE(wellFormed(b));
  // de Casteljau by Bernstein sums, independently.
  auto bern = [](int n, int i, double t) {
    double c = 1;
    for (int k = 0; k < i; ++k) c = c * (n - k) / (k + 1);
    return c * std::pow(t, i) * std::pow(1 - t, n - i);
  };
  for (int k = 0; k < 30; ++k) {
    const double u = (k % 7) / 6.0, v = (k % 5) / 4.0;
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int i = 0; i <= 3; ++i)
      for (int j = 0; j <= 5; ++j) x += bern(3, i, u) * bern(5, j, v) * net[size_t(i * 6 + j)];
    CHECK((x - evaluate(b, u, v)).norm() < 1e-14);
  }
}
