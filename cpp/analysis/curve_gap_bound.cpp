#include "analysis/curve_gap_bound.hpp"

#include <algorithm>
#include <cmath>

#include "bezier/bernstein.hpp"
#include "common/errors.hpp"
#include "expr/budget.hpp"
#include "expr/interval.hpp"
#include "expr/program.hpp"

namespace pdesurf {

namespace {

// The Bernstein coefficients of the same polynomial on [a, b] ⊂ [0, 1] (two de Casteljau
// splits): their hull encloses its values there.
std::vector<double> restricted(std::vector<double> c, double a, double b) {
  const int n = static_cast<int>(c.size()) - 1;
  for (int r = 1; r <= n; ++r)  // [0, b]: the left part of the split at b (in place, backwards)
    for (int k = n; k >= r; --k) c[size_t(k)] = (1 - b) * c[size_t(k) - 1] + b * c[size_t(k)];
  const double t = b > 0 ? a / b : 0.0;
  for (int r = 1; r <= n; ++r)  // [a, b]: the right part of that at a / b (in place, forwards)
    for (int k = 0; k <= n - r; ++k) c[size_t(k)] = (1 - t) * c[size_t(k)] + t * c[size_t(k) + 1];
  return c;
}

struct Piece {
  double a, b;
};

}  // namespace

CurveGap boundCurveGap(const std::array<Expr, 3>& f, double v0, double v1, const std::vector<Eigen::Vector3d>& B, double tol, int maxPieces, size_t* work) {
  const double k = v1 - v0;  // dv/ds
  CurveGap out;
  // First the distance at kScanPoints evenly spaced points: a border the degree cannot follow
  // (a curved one, a spike as wide as the scan's spacing) is found without derivatives.
  {
    const ExprProgram values(std::vector<Expr>{f[0], f[1], f[2]});
    std::vector<double> s(kScanPoints), vs(kScanPoints), at(3 * kScanPoints);
    for (int j = 0; j < kScanPoints; ++j) s[size_t(j)] = double(j) / (kScanPoints - 1), vs[size_t(j)] = v0 + k * s[size_t(j)];
    double* outs[3] = {at.data(), at.data() + kScanPoints, at.data() + 2 * kScanPoints};
    values.runAll(vs.data(), nullptr, kScanPoints, outs);
    const int n = static_cast<int>(B.size()) - 1;
    std::vector<double> w(size_t(n) + 1);
    double worst = -1.0;
    for (int j = 0; j < kScanPoints; ++j) {
      bernsteinValues(n, s[size_t(j)], w.data());
      Eigen::Vector3d g(outs[0][j], outs[1][j], outs[2][j]);
      for (int i = 0; i <= n; ++i) g -= w[size_t(i)] * B[size_t(i)];
      const double gap = g.norm();
      if (!(gap <= worst)) worst = gap, out.s = s[size_t(j)];
    }
    if (!(worst <= tol)) {
      out.verdict = CurveGap::Found, out.gap = worst;
      return out;
    }
  }
  // Then the proof, with the derivatives built under a budget of their own (the scene's
  // derivations keep theirs): an edge whose third derivative would swell past it is undecided.
  std::array<std::array<Expr, 3>, 4> d;  // d[r][c]: the r-th derivative of f_c in v
  d[0] = f;
  try {
    ExprBudget nodes(kCurveGapNodes, "the proof of a Bezier border");
    for (int r = 1; r <= 3; ++r)
      for (int c = 0; c < 3; ++c) d[size_t(r)][size_t(c)] = derivative(d[size_t(r) - 1][size_t(c)], ExprVar::V);
  } catch (const Error& e) {
    if (e.code() != ErrorCode::TooLarge) throw;
    out.verdict = CurveGap::Undecided, out.gap = INFINITY;
    return out;
  }
  std::vector<Expr> roots;
  for (int r = 0; r <= 2; ++r)
    for (int c = 0; c < 3; ++c) roots.push_back(d[size_t(r)][size_t(c)]);
  const ExprProgram values(roots);
  const std::array<IntervalProgram, 3> third = {IntervalProgram(d[3][0]), IntervalProgram(d[3][1]), IntervalProgram(d[3][2])};
  // B and its derivatives in s, per coordinate, in Bernstein form.
  std::array<std::array<std::vector<double>, 3>, 4> b;
  for (int c = 0; c < 3; ++c) {
    for (const Eigen::Vector3d& p : B) b[0][size_t(c)].push_back(p(c));
    for (int r = 1; r <= 3; ++r) b[size_t(r)][size_t(c)] = bernsteinDerivativeCoefs(b[0][size_t(c)], r);
  }
  const auto bezierAt = [&](int c, int r, double s) {
    const std::vector<double>& coefs = b[size_t(r)][size_t(c)];
    return coefs.empty() ? 0.0 : bernsteinSum(coefs.data(), static_cast<int>(coefs.size()) - 1, s);
  };
  const double k2 = k * k, k3 = k2 * k;
  // One piece: the values program at its middle, three enclosures, the Bernstein restrictions.
  const size_t perPiece = values.instructions() + third[0].steps() + third[1].steps() + third[2].steps() + 3 * B.size() * B.size();
  std::vector<Piece> level = {{0.0, 1.0}}, next;
  while (!level.empty()) {
    const size_t cost = perPiece * level.size();
    if (out.pieces + static_cast<int>(level.size()) > maxPieces || (work && cost > *work)) {
      out.verdict = CurveGap::Undecided, out.gap = INFINITY, out.s = level.front().a;
      return out;
    }
    out.pieces += static_cast<int>(level.size());
    if (work) *work -= cost;
    const size_t m = level.size();
    std::vector<double> vs(m);
    for (size_t i = 0; i < m; ++i) vs[i] = v0 + k * 0.5 * (level[i].a + level[i].b);
    std::vector<double> at(9 * m);
    double* outs[9];
    for (int r = 0; r < 9; ++r) outs[r] = at.data() + size_t(r) * m;
    values.runAll(vs.data(), nullptr, m, outs);
    next.clear();
    for (size_t i = 0; i < m; ++i) {
      const Piece& p = level[i];
      const double mid = 0.5 * (p.a + p.b), h = p.b - p.a;
      const Interval vRange{std::min(v0 + k * p.a, v0 + k * p.b), std::max(v0 + k * p.a, v0 + k * p.b)};
      double gapSq = 0.0, boundSq = 0.0;
      for (int c = 0; c < 3; ++c) {
        // g = f(v(s)) - B(s) and its first two derivatives at the middle.
        const double g0 = outs[c][i] - bezierAt(c, 0, mid), g1 = outs[3 + c][i] * k - bezierAt(c, 1, mid),
                     g2 = outs[6 + c][i] * k2 - bezierAt(c, 2, mid);
        // The third derivative over the piece, f'''(v) k^3 - B''': its enclosure's largest magnitude.
        const Interval vars[2] = {vRange, {0.0, 0.0}};
        const Interval f3 = third[size_t(c)].run(vars);
        double bLo = 0.0, bHi = 0.0;
        if (!b[3][size_t(c)].empty()) {
          const std::vector<double> r = restricted(b[3][size_t(c)], p.a, p.b);
          bLo = *std::min_element(r.begin(), r.end()), bHi = *std::max_element(r.begin(), r.end());
        }
        const double lo = std::min(f3.lo * k3, f3.hi * k3) - bHi, hi = std::max(f3.lo * k3, f3.hi * k3) - bLo;
        const double g3 = std::max(std::abs(lo), std::abs(hi));
        // Taylor at the middle, |s - mid| <= h/2; a few ulps of the values for their rounding.
        const double bound = std::abs(g0) + std::abs(g1) * h / 2 + std::abs(g2) * h * h / 8 + g3 * h * h * h / 48 +
                             1e-15 * (std::abs(outs[c][i]) + std::abs(bezierAt(c, 0, mid)));
        gapSq += g0 * g0;
        boundSq += std::isfinite(bound) ? bound * bound : INFINITY;
      }
      const double gap = std::sqrt(gapSq), bound = std::sqrt(boundSq);
      if (!(gap <= tol)) {
        out.verdict = CurveGap::Found, out.gap = gap, out.s = mid;
        return out;
      }
      if (bound <= tol) {
        out.gap = std::max(out.gap, bound);
        continue;
      }
      next.push_back({p.a, mid});
      next.push_back({mid, p.b});
    }
    std::swap(level, next);
  }
  return out;
}

}  // namespace pdesurf
