#include "cad/derivative_bounds.hpp"

#include <cmath>

#include "basis/general_function.hpp"
#include "common/limits.hpp"
#include "expr/budget.hpp"
#include "expr/interval.hpp"
#include "expr/program.hpp"

namespace pdesurf {
namespace {

// Relative slack for the rounding of the few operations of a closed-form bound.
constexpr double kRoundUp = 1.0 + 1e-13;
// Nodes built for one derivative of a pointwise part (as for general functions).
constexpr size_t kMaxDerivativeNodes = 200000;
// Halvings of a span at most when bounding a general function over it.
constexpr int kGeneralBoundHalvings = 6;

double fallingFactorial(int n, int k) {
  double f = 1.0;
  for (int i = 0; i < k; ++i) f *= (n - i);
  return f;
}

// max |Δ^k b_i| · n!/(n-k)!: the k-th derivative of Σ b_i B_i^n on [0, 1] is a Bernstein
// polynomial with those coefficients, bounded by the largest (convex hull).
double bernsteinBound(std::vector<double> b, int k) {
  const int n = int(b.size()) - 1;
  if (k > n) return 0.0;
  for (int r = 0; r < k; ++r)
    for (size_t i = 0; i + 1 < b.size() - size_t(r); ++i) b[i] = b[i + 1] - b[i];
  double m = 0.0;
  for (int i = 0; i + k <= n; ++i) m = std::max(m, std::abs(b[size_t(i)]));
  return m * fallingFactorial(n, k) * kRoundUp;
}

// The compiled forms of g^(k): an interval program for enclosures, a point program for samples.
struct Compiled {
  std::shared_ptr<const IntervalProgram> enclose;
  std::shared_ptr<const ExprProgram> sample;
};

Compiled compiled(const GeneralFunction& g, int k, GeneralBoundCache* cache) {
  const auto make = [&] {
    const Expr& d = g.derivativeExpr(k);
    return Compiled{std::make_shared<const IntervalProgram>(d), std::make_shared<const ExprProgram>(std::vector<Expr>{d})};
  };
  if (!cache) return make();
  const std::pair<const void*, int> key{static_cast<const void*>(&g), k};
  auto it = cache->programs.find(key);
  if (it == cache->programs.end()) {
    const Compiled c = make();
    it = cache->programs.emplace(key, GeneralBoundCache::Programs{c.enclose, c.sample}).first;
  }
  return Compiled{it->second.enclose, it->second.sample};
}

using Bound = GeneralBoundCache::Bound;

// Interval arithmetic overestimates (each occurrence of v varies on its own); where the
// enclosure is far above the values at the ends and the middle, halve the interval, up to
// `depth` times: the overestimate shrinks with the width. Every interval's answer is kept
// (refinement halves spans, whose halves were found here before) with what it depends on:
// one that never met the depth limit is the same for any deeper limit.
Bound boundGeneral(const GeneralFunction& g, int k, double a, double b, int depth, const Compiled& c,
                   GeneralBoundCache* cache) {
  const std::tuple<const void*, int, double, double> key{static_cast<const void*>(&g), k, a, b};
  if (cache) {
    const auto it = cache->bounds.find(key);
    if (it != cache->bounds.end() && (it->second.limited ? it->second.levels == depth : it->second.levels <= depth))
      return it->second;
  }
  const Interval vars[2] = {{a, b}, {0.0, 0.0}};
  if (cache && cache->work) cache->work->charge(kIntervalStepCost * double(c.enclose->steps()) + 3.0 * double(c.sample->instructions()));
  const double enclosed = c.enclose->run(vars).magnitude();
  Bound r{enclosed, 0, true};
  if (depth > 0) {
    const double mid = 0.5 * (a + b);
    const double at[3] = {a, mid, b};
    double values[3];
    c.sample->run(at, nullptr, 3, values);
    double seen = 0.0;
    for (double x : values) seen = std::max(seen, std::abs(x));  // NaN: not seen, so halve
    if (enclosed <= 4 * seen + 1e-300) {
      r = Bound{enclosed, 0, false};
    } else {
      const Bound left = boundGeneral(g, k, a, mid, depth - 1, c, cache);
      const Bound right = boundGeneral(g, k, mid, b, depth - 1, c, cache);
      r = Bound{std::max(left.value, right.value), 1 + std::max(left.levels, right.levels), left.limited || right.limited};
    }
  }
  if (cache) cache->bounds[key] = r;
  return r;
}

double boundGeneral(const GeneralFunction& g, int k, double a, double b, GeneralBoundCache* cache) {
  return boundGeneral(g, k, a, b, kGeneralBoundHalvings, compiled(g, k, cache), cache).value;
}

}  // namespace

double boundUFactor(const UFactor& G, int m, double a, double b) {
  if (!G.bernstein.empty()) return bernsteinBound(G.bernstein, m);
  double total = 0.0;
  for (const ExpPoly& piece : G.pieces) {
    // G^{(m)} = Re Σ e^{c x} Q(x), x = u - s, Q = (c + d/dx)^m P.
    const std::vector<cplx> q = derivativePoly(piece.poly, piece.rate, m);
    const double xa = a - piece.shift, xb = b - piece.shift;
    const double growth = std::exp(std::max(piece.rate.real() * xa, piece.rate.real() * xb));
    const double x = std::max(std::abs(xa), std::abs(xb));
    double poly = 0.0, power = 1.0;
    for (const cplx& c : q) {
      poly += std::abs(c) * power;
      power *= x;
    }
    total += growth * poly;
  }
  return total * kRoundUp;
}

double boundVFunction(const VFunction& g, int k, double a, double b) {
  const double w = std::abs(g.w), wk = std::pow(w, k);
  switch (g.family) {
    case Family::Poly: {
      if (k > g.n) return 0.0;
      const double x = std::max(std::abs(a - g.c), std::abs(b - g.c)) * w;
      return wk * fallingFactorial(g.n, k) * std::pow(x, g.n - k) * kRoundUp;
    }
    case Family::Cos:
    case Family::Sin: return wk * kRoundUp;
    case Family::Exp: return wk * std::exp(std::max(g.w * a, g.w * b)) * kRoundUp;
    case Family::Cosh:
    case Family::Sinh: return wk * std::cosh(w * std::max(std::abs(a), std::abs(b))) * kRoundUp;
    case Family::Bernstein: {
      std::vector<double> unit(size_t(g.degree) + 1, 0.0);
      unit[size_t(g.n)] = 1.0;
      return bernsteinBound(unit, k);
    }
    case Family::General: return boundGeneral(*g.general, k, a, b, nullptr);
  }
  return HUGE_VAL;
}

std::array<Eigen::MatrixXd, 3> boundPartials(const SeparableSurface& s, int du, int dv,
                                              const std::vector<double>& uBreaks, const std::vector<double>& vBreaks,
                                              GeneralBoundCache* cache) {
  const int nu = int(uBreaks.size()) - 1, nv = int(vBreaks.size()) - 1;
  std::array<Eigen::MatrixXd, 3> out;
  for (int c = 0; c < 3; ++c) {
    const auto& terms = s.component[size_t(c)];
    // Σ_t U(i, t) V(j, t): the separable sum of bounds is itself a matrix product.
    Eigen::MatrixXd U(nu, Eigen::Index(terms.size())), V(nv, Eigen::Index(terms.size()));
    for (size_t t = 0; t < terms.size(); ++t) {
      for (int i = 0; i < nu; ++i) U(i, Eigen::Index(t)) = boundUFactor(terms[t].G, du, uBreaks[size_t(i)], uBreaks[size_t(i) + 1]);
      const VFunction& g = terms[t].g;
      for (int j = 0; j < nv; ++j) {
        const double a = vBreaks[size_t(j)], b = vBreaks[size_t(j) + 1];
        if (cache && g.family == Family::General) {
          V(j, Eigen::Index(t)) = boundGeneral(*g.general, dv, a, b, cache);
        } else {
          V(j, Eigen::Index(t)) = boundVFunction(g, dv, a, b);
        }
      }
    }
    out[size_t(c)] = (U * V.transpose()) * kRoundUp;
    if (terms.empty()) out[size_t(c)] = Eigen::MatrixXd::Zero(nu, nv);
    if (const Expr& p = s.pointwise[size_t(c)]) {
      Expr d = p;
      {
        ExprBudget budget(kMaxDerivativeNodes, "a surface's pointwise part: its derivatives for the fit would");
        for (int r = 0; r < du; ++r) d = derivative(d, ExprVar::U);
        for (int r = 0; r < dv; ++r) d = derivative(d, ExprVar::V);
      }
      // Compiled once for every cell (each enclose() compiled its own), charged per cell.
      const IntervalProgram program(d);
      if (cache && cache->work) cache->work->charge(kIntervalStepCost * double(program.steps()) * nu * nv);
      for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
          const Interval vars[2] = {{vBreaks[size_t(j)], vBreaks[size_t(j) + 1]}, {uBreaks[size_t(i)], uBreaks[size_t(i) + 1]}};
          out[size_t(c)](i, j) += program.run(vars).magnitude();
        }
    }
  }
  return out;
}

}  // namespace pdesurf
