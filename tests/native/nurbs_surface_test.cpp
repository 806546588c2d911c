// NURBS surfaces (issue 40): the B-spline functions of the expression language (expr/spline.hpp)
// against an independent Cox–de Boor recursion; "surface" patches given as NURBS against an
// independent rational evaluation with their first and second partials; blends by reference
// to random NURBS surfaces (open and closed in v, polynomial and rational) certified; bad
// NURBS data refused by name.
#include <doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <random>

#include "analysis/join_certificate.hpp"
#include "expr/expr.hpp"
#include "expr/interval.hpp"
#include "expr/spline.hpp"
#include "expr/taylor.hpp"
#include "scene/scene.hpp"
#include "test_util.hpp"

using namespace pdesurf;
using namespace pdesurf::testing;
using json = nlohmann::json;

namespace {

// N_{i,p}(x) by the recursion of its definition; at the domain's end the last non-empty piece
// (right-continuous elsewhere), as the evaluator's convention.
double basis(const std::vector<double>& t, int i, int p, double x, int n) {
  if (p == 0) {
    int last = n - 1;
    while (t[size_t(last)] == t[size_t(last) + 1]) --last;
    if (x >= t[size_t(n)]) return i == last ? 1.0 : 0.0;
    return t[size_t(i)] <= x && x < t[size_t(i) + 1] ? 1.0 : 0.0;
  }
  double r = 0.0;
  const double d1 = t[size_t(i + p)] - t[size_t(i)], d2 = t[size_t(i + p + 1)] - t[size_t(i + 1)];
  if (d1 > 0) r += (x - t[size_t(i)]) / d1 * basis(t, i, p - 1, x, n);
  if (d2 > 0) r += (t[size_t(i + p + 1)] - x) / d2 * basis(t, i + 1, p - 1, x, n);
  return r;
}

// d^k N_{i,p}/dx^k: p (N_{i,p-1}/(t_{i+p}-t_i) - N_{i+1,p-1}/(t_{i+p+1}-t_{i+1})), recursively.
double basisDerivative(const std::vector<double>& t, int i, int p, double x, int n, int k) {
  if (k == 0) return basis(t, i, p, x, n);
  if (p == 0) return 0.0;
  double r = 0.0;
  const double d1 = t[size_t(i + p)] - t[size_t(i)], d2 = t[size_t(i + p + 1)] - t[size_t(i + 1)];
  if (d1 > 0) r += p / d1 * basisDerivative(t, i, p - 1, x, n, k - 1);
  if (d2 > 0) r -= p / d2 * basisDerivative(t, i + 1, p - 1, x, n, k - 1);
  return r;
}

// n + p + 1 knots over [a, b]: clamped or not, interior knots repeated up to maxRepeat (p) times.
std::vector<double> randomKnots(std::mt19937& rng, int p, int n, double a, double b, bool clamped, int maxRepeat = -1) {
  if (maxRepeat < 0) maxRepeat = p;
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> interior;
  while (int(interior.size()) < n - p - 1) {
    const double k = a + (b - a) * (0.05 + 0.9 * U(rng));
    const int m = std::min<int>(n - p - 1 - int(interior.size()), 1 + int(U(rng) * (U(rng) < 0.3 ? p : 1)));
    for (int r = 0; r < std::max(1, std::min(m, maxRepeat)); ++r) interior.push_back(k);
  }
  std::sort(interior.begin(), interior.end());
  std::vector<double> t;
  const double h = (b - a) / (n - p + 1);
  for (int r = 0; r <= p; ++r) t.push_back(clamped ? a : a - (p - r) * h);
  t.insert(t.end(), interior.begin(), interior.end());
  for (int r = 0; r <= p; ++r) t.push_back(clamped ? b : b + r * h);
  return t;
}

struct RandomNurbs {
  int p, q, nt, nv;
  std::vector<double> tk, vk;
  std::vector<Eigen::Vector3d> P;  // row-major, rows along t
  std::vector<double> W;
  json scene;  // the "nurbs" field
};

// A gently curved sheet over x in [x0, x0 + 1], y in [0, 1], at height z0: no folds.
// smoothBorders: its t-borders have no corner (every v-knot repeated at most q - 1 times, q >= 2):
// a tangent or curvature blend along a corner cannot be smooth there.
RandomNurbs randomNurbs(std::mt19937& rng, double x0, double z0, bool rational, bool clampedOnly = false, bool smoothBorders = false) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  RandomNurbs s;
  s.p = 1 + int(U(rng) * 5), s.q = (smoothBorders ? 2 : 1) + int(U(rng) * (smoothBorders ? 4 : 5));
  s.nt = s.p + 1 + int(U(rng) * 5), s.nv = s.q + 1 + int(U(rng) * 5);
  const double t0 = -1 + 2 * U(rng), v0 = -1 + 2 * U(rng);
  const double t1 = t0 + 0.5 + 2 * U(rng), v1 = v0 + 0.5 + 2 * U(rng);
  s.tk = randomKnots(rng, s.p, s.nt, t0, t1, clampedOnly || U(rng) < 0.7);
  s.vk = randomKnots(rng, s.q, s.nv, v0, v1, clampedOnly || U(rng) < 0.7, smoothBorders ? s.q - 1 : s.q);
  json points = json::array(), weights = json::array();
  for (int i = 0; i < s.nt; ++i) {
    json row = json::array(), wrow = json::array();
    for (int j = 0; j < s.nv; ++j) {
      const Eigen::Vector3d P(x0 + double(i) / (s.nt - 1), double(j) / (s.nv - 1), z0 + 0.15 * (U(rng) - 0.5));
      const double w = rational ? 0.5 + 1.5 * U(rng) : 1.0;
      s.P.push_back(P);
      s.W.push_back(w);
      row.push_back({P.x(), P.y(), P.z()});
      wrow.push_back(w);
    }
    points.push_back(row);
    weights.push_back(wrow);
  }
  s.scene = {{"degree", {s.p, s.q}}, {"knots", {s.tk, s.vk}}, {"points", points}};
  if (rational) s.scene["weights"] = weights;
  return s;
}

// The surface's partial ∂^{a+b}/∂t^a ∂v^b (a + b <= 2) from the homogeneous form by the quotient rule.
Eigen::Vector3d reference(const RandomNurbs& s, double t, double v, int a, int b) {
  // A(t, v) = Σ w P N M and w(t, v) = Σ w N M, with their partials up to (a, b).
  Eigen::Vector3d A[3][3];
  double w[3][3] = {};
  for (int da = 0; da <= a; ++da)
    for (int db = 0; db <= b; ++db) {
      A[da][db].setZero();
      for (int i = 0; i < s.nt; ++i) {
        const double Ni = basisDerivative(s.tk, i, s.p, t, s.nt, da);
        if (Ni == 0) continue;
        for (int j = 0; j < s.nv; ++j) {
          const double f = Ni * basisDerivative(s.vk, j, s.q, v, s.nv, db) * s.W[size_t(i * s.nv + j)];
          A[da][db] += f * s.P[size_t(i * s.nv + j)];
          w[da][db] += f;
        }
      }
    }
  const Eigen::Vector3d X = A[0][0] / w[0][0];
  if (a == 0 && b == 0) return X;
  if (a + b == 1) {
    const int da = a, db = b;
    return (A[da][db] - w[da][db] * X) / w[0][0];
  }
  const Eigen::Vector3d Xt = (A[1][0] - w[1][0] * X) / w[0][0];
  const Eigen::Vector3d Xv = (A[0][1] - w[0][1] * X) / w[0][0];
  if (a == 2) return (A[2][0] - 2 * w[1][0] * Xt - w[2][0] * X) / w[0][0];
  if (b == 2) return (A[0][2] - 2 * w[0][1] * Xv - w[0][2] * X) / w[0][0];
  return (A[1][1] - w[1][1] * X - w[1][0] * Xv - w[0][1] * Xt) / w[0][0];  // a = b = 1
}

json surfacePatch(const std::string& name, const json& nurbs) { return {{"name", name}, {"kind", "surface"}, {"nurbs", nurbs}}; }

// A vector, not a json: a braced list of one object is that object to some compilers (clang
// in the wasm build), an array of it to others.
json sceneOf(const std::vector<json>& patches) {
  return {{"format", "pdesurf-scene"}, {"version", 4}, {"patches", json(patches)}};
}

}  // namespace

TEST_CASE("nurbs: B-spline functions agree with the Cox–de Boor recursion, their derivatives, enclosures and Taylor series") {
  std::mt19937 rng(20261205);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  double worst = 0.0;
  int checks = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int p = 1 + int(U(rng) * 5);  // 1..5 (their derivatives take degrees 0..4)
    const int n = p + 1 + int(U(rng) * 7);
    const std::vector<double> t = randomKnots(rng, p, n, -2 * U(rng), 1 + 3 * U(rng), U(rng) < 0.6);
    std::vector<double> c(static_cast<size_t>(n), 0.0);
    for (double& x : c) x = -3 + 6 * U(rng);
    REQUIRE(SplineFn::problem(p, t, c).empty());
    const auto f = std::make_shared<const SplineFn>(p, t, c);
    const Expr e = spline(f, variable(ExprVar::V));
    for (int s = 0; s <= 40; ++s) {
      const double x = s == 0 ? f->lo() : s == 40 ? f->hi() : f->lo() + (f->hi() - f->lo()) * U(rng);
      for (int k = 0; k <= std::min(p, 3); ++k) {
        double want = 0.0;
        for (int i = 0; i < n; ++i) want += c[size_t(i)] * basisDerivative(t, i, p, x, n, k);
        const double got = f->derivativeAt(x, k);
        double scale = 1.0;
        for (double y : c) scale = std::max(scale, std::abs(y));
        worst = std::max(worst, std::abs(got - want) / (scale * std::pow(10.0, k)));
        CHECK(std::abs(got - want) <= 1e-11 * scale * std::pow(1 + 1.0 / (f->hi() - f->lo()), 3 * k) * std::pow(10.0, k));
        ++checks;
      }
      // The expression's value, its symbolic derivative and its Taylor series say the same.
      const double vars[2] = {x, 0.0};
      CHECK(evaluate(*e, vars) == f->eval(x));
      if (p >= 1 && x > f->lo() && x < f->hi()) {
        const Expr d = derivative(e, ExprVar::V);
        const auto series = taylorCoefficients(*e, ExprVar::V, vars, 3);
        CHECK(evaluate(*d, vars) == doctest::Approx(series[1]).epsilon(1e-12).scale(1.0));
        if (p >= 2) CHECK(2 * series[2] == doctest::Approx(f->derivativeAt(x, 2)).epsilon(1e-12).scale(1.0));
      }
    }
    // Enclosures hold the values sampled on random sub-intervals, some reaching past the
    // domain's ends (an argument's enclosure widened by rounding, a curve leaving it).
    for (int s = 0; s < 14; ++s) {
      const double reach = s < 10 ? 0.0 : (s < 12 ? 1e-15 : 0.05) * (f->hi() - f->lo());
      double a = f->lo() - reach + (f->hi() - f->lo() + 2 * reach) * U(rng), b = f->lo() - reach + (f->hi() - f->lo() + 2 * reach) * U(rng);
      if (s % 2) a = f->lo() - reach, b = s >= 10 ? f->hi() + reach : b;
      if (a > b) std::swap(a, b);
      const Interval box[2] = {{a, b}, {0, 0}};
      const Interval r = enclose(e, box);
      REQUIRE(r.bounded());
      for (int k = 0; k <= 20; ++k) {
        const double x = a + (b - a) * k / 20;
        CHECK(r.lo <= f->eval(x));
        CHECK(f->eval(x) <= r.hi);
      }
    }
  }
  MESSAGE(checks << " values and derivatives, worst scaled difference " << worst);
}

TEST_CASE("nurbs: a surface given as NURBS is the rational surface, with its partials, over random degrees and knots") {
  std::mt19937 rng(4040);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  double worst = 0.0;
  for (int trial = 0; trial < 60; ++trial) {
    CAPTURE(trial);
    const RandomNurbs s = randomNurbs(rng, 0.0, 0.0, trial % 2 == 1);
    const Scene scene = parseScene(sceneOf({surfacePatch("s", s.scene)}).dump());
    const auto solved = solveScene(scene);
    const SeparableSurface& S = solved.at(0).surface;
    CHECK(S.u0 == s.tk[size_t(s.p)]);
    CHECK(S.v1 == s.vk[size_t(s.nv)]);
    for (int k = 0; k < 25; ++k) {
      const double t = k < 2 ? (k ? S.u1 : S.u0) : S.u0 + (S.u1 - S.u0) * U(rng);
      const double v = k < 2 ? (k ? S.v0 : S.v1) : S.v0 + (S.v1 - S.v0) * U(rng);
      for (const auto& o : kPartialOrders) {
        const Eigen::Vector3d want = reference(s, t, v, o[0], o[1]), got = evalPoint(S, t, v, o[0], o[1]);
        const double scale = std::max(1.0, want.norm());
        CAPTURE(o[0]);
        CAPTURE(o[1]);
        CHECK((got - want).norm() <= 1e-11 * scale);
        worst = std::max(worst, (got - want).norm() / scale);
      }
    }
  }
  MESSAGE("worst relative difference of the points and partials: " << worst);
}

TEST_CASE("nurbs: the compiled partials share their bases along grid lines in either direction and pass NaN through") {
  // The program computes each knot vector's basis once per point and reuses it while the
  // argument repeats (a grid line along the other variable): rows of fixed t, rows of fixed v,
  // scattered points and NaN between them, against the independent rational evaluation.
  std::mt19937 rng(4041);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int trial = 0; trial < 12; ++trial) {
    CAPTURE(trial);
    const RandomNurbs s = randomNurbs(rng, 0.0, 0.0, trial % 2 == 1);
    const Scene scene = parseScene(sceneOf({surfacePatch("s", s.scene)}).dump());
    const auto solved = solveScene(scene);
    const SeparableSurface& S = solved.at(0).surface;
    std::vector<double> t, v;
    for (int row = 0; row < 4; ++row) {
      const double fixed = U(rng);
      for (int k = 0; k <= 9; ++k) {
        const double along = k / 9.0;
        t.push_back(S.u0 + (S.u1 - S.u0) * (row % 2 ? fixed : along));
        v.push_back(S.v0 + (S.v1 - S.v0) * (row % 2 ? along : fixed));
      }
      t.push_back(std::nan("")), v.push_back(std::nan(""));
      for (int k = 0; k < 5; ++k) t.push_back(S.u0 + (S.u1 - S.u0) * U(rng)), v.push_back(S.v0 + (S.v1 - S.v0) * U(rng));
    }
    const size_t n = t.size();
    std::array<std::vector<std::vector<double>>, 3> out;
    for (int c = 0; c < 3; ++c) {
      const auto program = pointwiseProgramOf(S, c);
      REQUIRE(program);
      REQUIRE(program->outputs() == 6);
      out[size_t(c)].assign(6, std::vector<double>(n));
      double* outs[6];
      for (int r = 0; r < 6; ++r) outs[r] = out[size_t(c)][size_t(r)].data();
      program->runAll(v.data(), t.data(), n, outs);
    }
    for (size_t i = 0; i < n; ++i)
      for (int r = 0; r < 6; ++r) {
        const Eigen::Vector3d got(out[0][size_t(r)][i], out[1][size_t(r)][i], out[2][size_t(r)][i]);
        if (std::isnan(t[i])) {  // NaN, or 0 where the partial is 0 symbolically (degree 1: no second derivative)
          if (r == 0) CHECK(got.array().isNaN().all());
          for (int c = 0; c < 3; ++c) CHECK((std::isnan(got[c]) || got[c] == 0.0));
          continue;
        }
        const Eigen::Vector3d want = reference(s, t[i], v[i], kPartialOrders[r][0], kPartialOrders[r][1]);
        CAPTURE(i);
        CAPTURE(r);
        CHECK((got - want).norm() <= 1e-11 * std::max(1.0, want.norm()));
      }
  }
}

TEST_CASE("nurbs: a rational quadratic circle is a circle, and a cylinder made of two is closed in v") {
  // The standard 9-point rational quadratic circle, v in [0, 1], swept along z (degree 1 in t).
  const double r2 = std::sqrt(0.5);
  const double cx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, cy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
  json points = json::array(), weights = json::array();
  for (int i = 0; i < 2; ++i) {
    json row = json::array(), w = json::array();
    for (int j = 0; j < 9; ++j) row.push_back({2 * cx[j], 2 * cy[j], double(i)}), w.push_back(j % 2 ? r2 : 1.0);
    points.push_back(row), weights.push_back(w);
  }
  const json nurbs = {{"degree", {1, 2}}, {"knots", {{0, 0, 1, 1}, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}}}, {"points", points}, {"weights", weights}};
  const Scene scene = parseScene(sceneOf({surfacePatch("tube", nurbs)}).dump());
  const auto solved = solveScene(scene);
  double worst = 0.0;
  for (int k = 0; k <= 400; ++k) {
    const Eigen::Vector3d p = evalPoint(solved[0].surface, 0.3, k / 400.0);
    worst = std::max(worst, std::abs(std::hypot(p.x(), p.y()) - 2.0));
  }
  CHECK(worst < 1e-14);
  // Closed in v: the seam meets in position and tangent direction (the data's own seam; the
  // certificate certifies the seams of the patches pdesurf solves).
  for (double t : {0.0, 0.5, 1.0}) {
    const SeparableSurface& S = solved[0].surface;
    CHECK((evalPoint(S, t, 0.0) - evalPoint(S, t, 1.0)).norm() < 1e-15);
    CHECK(evalPoint(S, t, 0.0, 0, 1).normalized().dot(evalPoint(S, t, 1.0, 0, 1).normalized()) > 1 - 1e-15);
  }
  MESSAGE("radius error " << worst);
}

TEST_CASE("nurbs: blends by reference to random NURBS surfaces keep the continuity each end asks for") {
  std::mt19937 rng(40);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const char* levels[3] = {"position", "tangency", "curvature"};
  int joins = 0;
  double worstG0 = 0, worstG1 = 0, worstG2 = 0, worstSize = 0;
  // Each blend is a refined modal solve and a certificate (~0.3 s natively, 4 s under
  // AddressSanitizer): a third of them in wasm, three (G0, G1, G2 at u0) under ASan, the same
  // seeds (the suite's budget).
  const int trials = kAddressSanitizer ? 3 : kSlowLongDouble ? 12 : 36;
  for (int trial = 0; trial < trials; ++trial) {
    CAPTURE(trial);
    // Both sheets over the same v: the blend's v is theirs, so their v-knots span one domain.
    RandomNurbs lower = randomNurbs(rng, -1.0, 0.0, trial % 2 == 0, true, true);
    RandomNurbs upper = randomNurbs(rng, 1.0, 0.8, trial % 3 == 0, true, true);
    const double a = upper.vk.front(), b = upper.vk.back();
    for (double& k : upper.vk) k = lower.vk.front() + (k - a) / (b - a) * (lower.vk.back() - lower.vk.front());
    upper.scene["knots"][1] = upper.vk;
    const int level = trial % 3;
    json ends = {{"u0", {{"surface", "lower"}, {"at", "t1"}, {"continuity", levels[level]}, {"flip", false}}},
                 {"u1", {{"surface", "upper"}, {"at", "t0"}, {"continuity", levels[(level + 1) % 3]}}}};
    const json blend = {{"name", "blend"}, {"kind", "pde"}, {"v_range", {lower.vk.front(), lower.vk.back()}}, {"ends", ends}};
    const json scene = sceneOf({blend, surfacePatch("lower", lower.scene), surfacePatch("upper", upper.scene)});
    const Scene sc = parseScene(scene.dump());
    const SceneReport r = checkScene(sc, solveScene(sc), 0);
    REQUIRE(r.joins.size() == 2);
    for (const JoinResult& j : r.joins) {
      CAPTURE(j.surface);
      CAPTURE(j.g0);
      CAPTURE(j.g1Deg);
      CAPTURE(j.g2Rel);
      CAPTURE(j.level);
      CAPTURE(j.degenerate);
      CAPTURE(j.worstV);
      CHECK(j.ok);
      CHECK(!j.fold);
      CAPTURE(j.size);
      // No blow-up: the sheets' diagonal is ~3.3. On an open v-range the PDE has no conditions
      // at the v ends and the method's continuation decides the blend there: up to 12 is
      // measured here (3 of 36 blends past 6); matching B-spline data at the ends to the order
      // smooth data get gave blends of 10^2..10^5 (methods/modal.cpp, kSplineDataMatch).
      CHECK(j.size < 20.0);
      worstSize = std::max(worstSize, j.size);
      ++joins;
      worstG0 = std::max(worstG0, j.g0);
      if (j.level >= 1) worstG1 = std::max(worstG1, j.g1Deg);
      if (j.level >= 2) worstG2 = std::max(worstG2, j.g2Rel);
    }
  }
  MESSAGE(joins << " joins to NURBS surfaces certified; worst G0 " << worstG0 << ", G1 " << worstG1 << " deg, G2 " << worstG2
                << "; largest blend " << worstSize);
}

TEST_CASE("nurbs: bad NURBS data is refused by name") {
  const json good = {{"degree", {1, 1}}, {"knots", {{0, 0, 1, 1}, {0, 0, 1, 1}}}, {"points", {{{0, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 0}}}}};
  auto errorWith = [&](const std::function<void(json&)>& edit) {
    json n = good;
    edit(n);
    return parseErrorOf(sceneOf({surfacePatch("s", n)}).dump());
  };
  CHECK(errorWith([](json&) {}) == "");
  CHECK(errorWith([](json& n) { n["degree"][0] = 26; }).find("patches[0].nurbs.degree[0]") != std::string::npos);
  CHECK(errorWith([](json& n) { n["knots"][1] = {0, 1, 0, 1}; }).find("patches[0].nurbs.knots[1]: knot 2 is smaller") != std::string::npos);
  CHECK(errorWith([](json& n) { n["knots"][0] = {0, 0, 1}; }).find("need 4 knots, not 3") != std::string::npos);
  CHECK(errorWith([](json& n) { n["knots"][0] = {0, 0, 0, 0}; }).find("domain") != std::string::npos);
  CHECK(errorWith([](json& n) { n["points"][1][0][2] = "nan"; }).find("patches[0].nurbs.points[1][0][2]") != std::string::npos);
  CHECK(errorWith([](json& n) { n["points"][1].erase(1); }).find("patches[0].nurbs.points[1]") != std::string::npos);
  CHECK(errorWith([](json& n) { n["weights"] = {{1, 1}, {1, 0}}; }).find("patches[0].nurbs.weights[1][1]: a weight must be positive") != std::string::npos);
  CHECK(errorWith([](json& n) { n["points"].push_back(n["points"][1]), n["points"].push_back(n["points"][1]); n["knots"][0] = {0, 0, 0.5, 0.5, 1, 1}; })
            .find("patches[0].nurbs.knots[0]: the knot 0.500000 is repeated 2 times inside the domain") != std::string::npos);
  CHECK(errorWith([](json& n) { n["points"] = json::array(); for (int i = 0; i < 65; ++i) n["points"].push_back(json::array({{0, 0, 0}})); })
            .find("TooLarge") == std::string::npos);  // 65 × 1 is within the count (refused for its degree instead)
  json big = good;
  big["points"] = json::array();
  for (int i = 0; i < 129; ++i) {
    json row = json::array();
    for (int k = 0; k < 129; ++k) row.push_back({0, 0, 0});
    big["points"].push_back(row);
  }
  CHECK(parseErrorOf(sceneOf({surfacePatch("s", big)}).dump()).rfind("TooLarge: patches[0].nurbs.points", 0) == 0);
  json both = surfacePatch("s", good);
  both["x"] = "t";
  CHECK(parseErrorOf(sceneOf({both}).dump()).find("either by \"nurbs\" or by x, y, z") != std::string::npos);
  json outside = surfacePatch("s", good);
  outside["t_range"] = {0, 2};
  CHECK(parseErrorOf(sceneOf({outside}).dump()).find("patches[0].t_range: leaves the NURBS surface's domain in t") != std::string::npos);
  json old = sceneOf({surfacePatch("s", good)});
  old["version"] = 3;
  CHECK(parseErrorOf(old.dump()).find("needs scene version 4") != std::string::npos);
}

namespace {

// The typed strip `s` (a polynomial of degree <= 2 in t and in v) as a Bézier surface of degree
// 2 × 2: its Bernstein coefficients from its values at three points a direction (exact).
json asNurbs(const SeparableSurface& s) {
  const double B[3][3] = {{1, 0, 0}, {0.25, 0.5, 0.25}, {0, 0, 1}};  // B_j(x_i) at x = 0, 1/2, 1
  Eigen::Matrix3d M;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) M(i, j) = B[i][j];
  const Eigen::Matrix3d Minv = M.inverse();
  json points = json::array();
  std::array<Eigen::Matrix3d, 3> values;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d p = evalPoint(s, s.u0 + (s.u1 - s.u0) * i / 2.0, s.v0 + (s.v1 - s.v0) * j / 2.0);
      for (int c = 0; c < 3; ++c) values[size_t(c)](i, j) = p[c];
    }
  std::array<Eigen::Matrix3d, 3> coef;
  for (int c = 0; c < 3; ++c) coef[size_t(c)] = Minv * values[size_t(c)] * Minv.transpose();
  for (int i = 0; i < 3; ++i) {
    json row = json::array();
    for (int j = 0; j < 3; ++j) row.push_back({coef[0](i, j), coef[1](i, j), coef[2](i, j)});
    points.push_back(row);
  }
  return {{"degree", {2, 2}}, {"knots", {{s.u0, s.u0, s.u0, s.u1, s.u1, s.u1}, {s.v0, s.v0, s.v0, s.v1, s.v1, s.v1}}}, {"points", points}};
}

}  // namespace

TEST_CASE("nurbs: a Bézier fill with its borders by reference to NURBS strips is the fill to the typed strips, certified") {
  const json typed = json::parse(readText(examplePath("fill-four-strips.json")));
  const Scene original = parseScene(typed.dump());
  const auto solvedTyped = solveScene(original);
  json rebuilt = typed;
  int replaced = 0;
  for (json& p : rebuilt["patches"]) {
    if (p["kind"] != "surface") continue;
    const SeparableSurface& s = solvedNamed(solvedTyped, p["name"].get<std::string>()).surface;
    json n = {{"name", p["name"]}, {"kind", "surface"}, {"nurbs", asNurbs(s)}};
    p = n;
    ++replaced;
  }
  CHECK(replaced == 8);
  const Scene scene = parseScene(rebuilt.dump());
  const auto solved = solveScene(scene);
  // The strips are the same surfaces (a polynomial of degree 2 in Bernstein form).
  double worstStrip = 0.0;
  for (const SolvedPatch& sp : solved) {
    if (sp.patch->kind != PatchKind::Primary) continue;
    const SeparableSurface& a = solvedNamed(solvedTyped, sp.patch->name).surface;
    for (int k = 0; k <= 10; ++k)
      worstStrip = std::max(worstStrip, (evalPoint(a, a.u0 + (a.u1 - a.u0) * k / 10, a.v0 + (a.v1 - a.v0) * (10 - k) / 10) -
                                         evalPoint(sp.surface, a.u0 + (a.u1 - a.u0) * k / 10, a.v0 + (a.v1 - a.v0) * (10 - k) / 10)).norm());
  }
  CHECK(worstStrip < 1e-13);
  // The fill solved against the NURBS strips' borders is the fill solved against the typed ones.
  const SeparableSurface& f0 = solvedNamed(solvedTyped, "fill").surface;
  const SeparableSurface& f1 = solvedNamed(solved, "fill").surface;
  double worstFill = 0.0;
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j) worstFill = std::max(worstFill, (evalPoint(f0, i / 8.0, j / 8.0) - evalPoint(f1, i / 8.0, j / 8.0)).norm());
  CHECK(worstFill < 1e-9);
  const SceneReport r = checkScene(scene, solved, 0);
  CHECK(r.joins.size() >= 4);
  for (const JoinResult& j : r.joins) {
    CAPTURE(j.surface);
    CAPTURE(j.g0);
    CAPTURE(j.g1Deg);
    CHECK(j.ok);
  }
  MESSAGE("strips " << worstStrip << " apart, the fill " << worstFill << "; " << r.joins.size() << " joins certified");
}
