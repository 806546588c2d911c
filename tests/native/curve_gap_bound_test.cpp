// The proven distance between a typed curve and a Bézier curve fitted to it
// (analysis/curve_gap_bound.hpp): proven within the tolerance only where it is, a narrow
// feature between any samples found, the budget reported as undecided.
#include <doctest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "analysis/curve_gap_bound.hpp"
#include "bezier/bernstein.hpp"
#include "expr/parse.hpp"

using namespace pdesurf;

namespace {

std::array<Expr, 3> curve(const std::string& x, const std::string& y, const std::string& z) {
  const AllowedVariables v{true, false};
  return {parseExpression(x, {}, v), parseExpression(y, {}, v), parseExpression(z, {}, v)};
}

Eigen::Vector3d at(const std::array<Expr, 3>& f, double v) {
  const double vars[2] = {v, 0.0};
  return {evaluate(*f[0], vars), evaluate(*f[1], vars), evaluate(*f[2], vars)};
}

// The Bézier curve of degree n interpolating f(v(s)) at n + 1 Chebyshev points of s.
std::vector<Eigen::Vector3d> interpolate(const std::array<Expr, 3>& f, double v0, double v1, int n) {
  Eigen::MatrixXd A(n + 1, n + 1), rhs(n + 1, 3);
  std::vector<double> B(size_t(n) + 1);
  for (int k = 0; k <= n; ++k) {
    const double s = 0.5 * (1 - std::cos(M_PI * k / n));
    bernsteinValues(n, s, B.data());
    for (int j = 0; j <= n; ++j) A(k, j) = B[size_t(j)];
    rhs.row(k) = at(f, v0 + s * (v1 - v0)).transpose();
  }
  const Eigen::MatrixXd c = A.fullPivLu().solve(rhs);
  std::vector<Eigen::Vector3d> out;
  for (int j = 0; j <= n; ++j) out.push_back(c.row(j).transpose());
  return out;
}

// The largest distance over `count` evenly spaced points: what a sampled check sees.
double sampledGap(const std::array<Expr, 3>& f, double v0, double v1, const std::vector<Eigen::Vector3d>& B, int count) {
  const int n = static_cast<int>(B.size()) - 1;
  std::vector<double> w(size_t(n) + 1);
  double worst = 0.0;
  for (int k = 0; k < count; ++k) {
    const double s = double(k) / (count - 1);
    bernsteinValues(n, s, w.data());
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    for (int j = 0; j <= n; ++j) b += w[size_t(j)] * B[size_t(j)];
    worst = std::max(worst, (at(f, v0 + s * (v1 - v0)) - b).norm());
  }
  return worst;
}

}  // namespace

TEST_CASE("curve gap: a polynomial border is proven, a narrow spike between samples is found, a curved one fails at its fit") {
  // A cubic in v, fitted exactly by degree 5 (either direction along v).
  const auto cubic = curve("v", "0.3*v^3 - v", "0.2*v^2");
  for (const bool backwards : {false, true}) {
    const double v0 = backwards ? 1.0 : -1.0, v1 = -v0;
    const CurveGap g = boundCurveGap(cubic, v0, v1, interpolate(cubic, v0, v1, 5), 1e-9);
    CHECK(g.verdict == CurveGap::Within);
    CHECK(g.gap <= 1e-9);
    MESSAGE("cubic: proven in " << g.pieces << " pieces");
    CHECK(g.pieces < 4096);
  }
  // The same with a 0.3 spike 3e-4 wide between 129 and 256 evenly spaced samples (issue 38).
  const double c = 0.0039215686274509665;
  const auto spiked = curve("0", "v", "0.3*exp(-((v - " + std::to_string(c) + ")/0.0003)^2)");
  const auto flat = curve("0", "v", "0");
  const std::vector<Eigen::Vector3d> line = interpolate(flat, -0.5, 0.5, 5);
  CHECK(sampledGap(spiked, -0.5, 0.5, line, 256) < 1e-6);  // what the samples saw
  const CurveGap s = boundCurveGap(spiked, -0.5, 0.5, line, 1e-9);
  CHECK(s.verdict == CurveGap::Found);
  CHECK(s.gap > 1e-3);
  CHECK(std::abs(-0.5 + s.s - c) < 0.01);
  // A circle's arc at degree 6: the fit's own error, found (at least the tolerance, at most
  // what dense sampling sees).
  const auto arc = curve("cos(v)", "sin(v)", "0");
  const std::vector<Eigen::Vector3d> fit = interpolate(arc, 0.0, 2.0, 6);
  const CurveGap a = boundCurveGap(arc, 0.0, 2.0, fit, 1e-9);
  CHECK(a.verdict == CurveGap::Found);
  CHECK(a.gap > 1e-9);
  CHECK(a.gap <= sampledGap(arc, 0.0, 2.0, fit, 20001) * (1 + 1e-9));
  // An exponential at degree 12 (its fit within 1e-13): proven, in more than one piece; with
  // fewer pieces allowed, undecided, never proven.
  const auto grow = curve("exp(v)", "v", "exp(-v)");
  const std::vector<Eigen::Vector3d> twelve = interpolate(grow, -1.0, 1.0, 12);
  const CurveGap e = boundCurveGap(grow, -1.0, 1.0, twelve, 1e-9);
  CHECK(e.verdict == CurveGap::Within);
  MESSAGE("exp at degree 12: proven in " << e.pieces << " pieces");
  REQUIRE(e.pieces > 1);
  CHECK(boundCurveGap(grow, -1.0, 1.0, twelve, 1e-9, e.pieces - 1).verdict == CurveGap::Undecided);
  // The same from a scene's work left: charged level by level, undecided before it overdraws.
  size_t plenty = kCurveGapWork, little = 1000;
  CHECK(boundCurveGap(grow, -1.0, 1.0, twelve, 1e-9, kCurveGapPieces, &plenty).verdict == CurveGap::Within);
  CHECK(plenty < kCurveGapWork);
  CHECK(boundCurveGap(grow, -1.0, 1.0, twelve, 1e-9, kCurveGapPieces, &little).verdict == CurveGap::Undecided);
  CHECK(little <= 1000);
}

TEST_CASE("curve gap: random smooth curves with random narrow bumps are never proven within the tolerance when they are not") {
  std::mt19937 rng(38);
  std::uniform_real_distribution<double> U(-1, 1);
  int proven = 0, found = 0, undecided = 0;
  for (int trial = 0; trial < 60; ++trial) {
    CAPTURE(trial);
    // A random cubic plus, in two of three trials, a bump of random height and width.
    std::string x = std::to_string(U(rng)) + "*v + " + std::to_string(U(rng)) + "*v^3";
    std::string y = std::to_string(U(rng)) + " + v";
    const std::string base = std::to_string(U(rng)) + "*v^2";
    std::string z = base;
    if (trial % 3) {
      const double height = std::pow(10.0, -2 - 8 * std::abs(U(rng)));  // 1e-10 .. 1e-2
      const double width = std::pow(10.0, -1 - 3 * std::abs(U(rng))), centre = 0.9 * U(rng);
      char bump[160];
      std::snprintf(bump, sizeof bump, " + %.17g*exp(-((v - %.17g)/%.17g)^2)", height, centre, width);
      z += bump;
    }
    const auto f = curve(x, y, z);
    const std::vector<Eigen::Vector3d> B = interpolate(curve(x, y, base), -1, 1, 7);  // the fit without the bump
    const double dense = sampledGap(f, -1.0, 1.0, B, 200001);
    const CurveGap g = boundCurveGap(f, -1.0, 1.0, B, 1e-9);
    CAPTURE(z);
    CAPTURE(dense);
    if (g.verdict == CurveGap::Within) {
      ++proven;
      CHECK(dense <= 1e-9);
    } else if (g.verdict == CurveGap::Found) {
      ++found;
      CHECK(g.gap > 1e-9);
      CHECK(g.gap <= dense * (1 + 1e-6) + 1e-15);
    } else {
      ++undecided;
    }
  }
  MESSAGE(proven << " proven, " << found << " found, " << undecided << " undecided");
  CHECK(proven >= 20);
  CHECK(found >= 20);
}
