#include "expr/interval.hpp"

#include "expr/spline.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace pdesurf {
namespace {

constexpr double kInf = HUGE_VAL;
const Interval kWhole{-kInf, kInf};

// At least one ulp outward, by arithmetic rather than libm's nextafter (a call per end that
// cost a tenth of a fit's time): |x|·2^-52 is at least x's ulp, 2^-1074 covers 0 and the
// subnormals, and the nearest double to x ∓ that lies beyond x. Infinities stay.
double below(double x) { return std::abs(x) < kInf ? x - (std::abs(x) * 0x1p-52 + 0x1p-1074) : x; }
double above(double x) { return std::abs(x) < kInf ? x + (std::abs(x) * 0x1p-52 + 0x1p-1074) : x; }

Interval widen(double lo, double hi) {
  if (std::isnan(lo) || std::isnan(hi)) return kWhole;
  return {below(lo), above(hi)};
}
Interval hull4(double a, double b, double c, double d) {
  return widen(std::min(std::min(a, b), std::min(c, d)), std::max(std::max(a, b), std::max(c, d)));
}
bool contains(const Interval& x, double t) { return x.lo <= t && t <= x.hi; }

Interval mul(const Interval& a, const Interval& b) {
  if (!a.bounded() || !b.bounded()) return kWhole;
  return hull4(a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi);
}
Interval divide(const Interval& a, const Interval& b) {
  if (contains(b, 0.0) || !b.bounded()) return kWhole;
  return mul(a, widen(1.0 / b.hi, 1.0 / b.lo));
}

// x^n for an integer n >= 0.
Interval integerPower(const Interval& x, int n) {
  if (n == 0) return {1.0, 1.0};
  const double a = std::pow(x.lo, n), b = std::pow(x.hi, n);
  if (n % 2 == 1) return widen(a, b);
  if (contains(x, 0.0)) return widen(0.0, std::max(a, b));
  return widen(std::min(a, b), std::max(a, b));
}

// sin over x: the ends, plus ±1 where a peak (π/2 + 2kπ) or trough lies inside.
Interval sine(const Interval& x) {
  if (!x.bounded() || x.hi - x.lo >= 2 * M_PI) return {-1.0, 1.0};
  double lo = std::min(std::sin(x.lo), std::sin(x.hi)), hi = std::max(std::sin(x.lo), std::sin(x.hi));
  // Index of the first peak at or after x.lo; a slightly generous test keeps it an enclosure.
  const double peak = std::ceil((x.lo - M_PI / 2) / (2 * M_PI) - 1e-12) * 2 * M_PI + M_PI / 2;
  if (peak <= x.hi + 1e-12) hi = 1.0;
  const double trough = std::ceil((x.lo + M_PI / 2) / (2 * M_PI) - 1e-12) * 2 * M_PI - M_PI / 2;
  if (trough <= x.hi + 1e-12) lo = -1.0;
  Interval r = widen(lo, hi);
  return {std::max(r.lo, -1.0), std::min(r.hi, 1.0)};
}

Interval monotone(double (*f)(double), const Interval& x, bool increasing) {
  const double a = f(x.lo), b = f(x.hi);
  return increasing ? widen(a, b) : widen(b, a);
}

Interval call(ExprFn fn, const Interval& x) {
  if (!x.bounded()) return kWhole;
  switch (fn) {
    case ExprFn::Sqrt: return x.lo < 0 ? kWhole : Interval{std::max(0.0, widen(std::sqrt(x.lo), 0).lo), widen(0, std::sqrt(x.hi)).hi};
    case ExprFn::Exp: return monotone(std::exp, x, true);
    case ExprFn::Log: return x.lo <= 0 ? kWhole : monotone(std::log, x, true);
    case ExprFn::Sin: return sine(x);
    case ExprFn::Cos: return sine({x.lo + M_PI / 2 - 1e-15 * std::abs(x.lo), x.hi + M_PI / 2 + 1e-15 * std::abs(x.hi)});
    case ExprFn::Tan: {
      // A pole (π/2 + kπ) inside gives the whole line.
      const double pole = std::ceil((x.lo - M_PI / 2) / M_PI - 1e-12) * M_PI + M_PI / 2;
      if (pole <= x.hi + 1e-12) return kWhole;
      return monotone(std::tan, x, true);
    }
    case ExprFn::Asin: return (x.lo < -1 || x.hi > 1) ? kWhole : monotone(std::asin, x, true);
    case ExprFn::Acos: return (x.lo < -1 || x.hi > 1) ? kWhole : monotone(std::acos, x, false);
    case ExprFn::Atan: return monotone(std::atan, x, true);
    case ExprFn::Sinh: return monotone(std::sinh, x, true);
    case ExprFn::Tanh: return monotone(std::tanh, x, true);
    case ExprFn::Cosh: {
      const double hi = std::cosh(std::max(std::abs(x.lo), std::abs(x.hi)));
      return widen(contains(x, 0.0) ? 1.0 : std::cosh(std::min(std::abs(x.lo), std::abs(x.hi))), hi);
    }
    case ExprFn::Abs:
      if (x.lo >= 0) return x;
      if (x.hi <= 0) return {-x.hi, -x.lo};
      return {0.0, std::max(-x.lo, x.hi)};
    case ExprFn::Sign:
      if (x.lo > 0) return {1.0, 1.0};
      if (x.hi < 0) return {-1.0, -1.0};
      return {-1.0, 1.0};
    case ExprFn::General: return x;
  }
  return kWhole;
}

Interval power(const Interval& a, const ExprNode& exponent, const Interval& b) {
  if (exponent.op == ExprNode::Op::Const) {
    const double p = exponent.value;
    if (p == std::floor(p) && std::abs(p) <= 1024) {
      const Interval r = integerPower(a, int(std::abs(p)));
      return p >= 0 ? r : divide({1.0, 1.0}, r);
    }
    if (a.lo < 0) return kWhole;  // pow(negative, non-integer) is NaN
    if (a.lo == 0 && p > 0) return widen(0.0, std::pow(a.hi, p));
  }
  if (a.lo <= 0) return kWhole;
  // a^b = exp(b log a) on a > 0.
  return call(ExprFn::Exp, mul(b, call(ExprFn::Log, a)));
}

}  // namespace

bool Interval::bounded() const { return std::isfinite(lo) && std::isfinite(hi); }
double Interval::magnitude() const { return bounded() ? std::max(std::abs(lo), std::abs(hi)) : kInf; }

IntervalProgram::IntervalProgram(const Expr& root) {
  // Post-order over the DAG with an explicit stack: derived expressions can be thousands deep.
  std::unordered_map<const ExprNode*, int> index;
  std::vector<std::pair<const ExprNode*, bool>> stack{{root.get(), false}};
  while (!stack.empty()) {
    auto [n, expanded] = stack.back();
    stack.pop_back();
    if (index.count(n)) continue;
    if (!expanded) {
      stack.push_back({n, true});
      if (n->a && !index.count(n->a.get())) stack.push_back({n->a.get(), false});
      if (n->b && !index.count(n->b.get())) stack.push_back({n->b.get(), false});
      continue;
    }
    Step step{n};
    if (n->a) step.a = index.at(n->a.get());
    if (n->b) step.b = index.at(n->b.get());
    index[n] = int(steps_.size());
    steps_.push_back(step);
  }
  values_.resize(steps_.size());
}

Interval IntervalProgram::run(const Interval* vars) const {
  using Op = ExprNode::Op;
  for (size_t k = 0; k < steps_.size(); ++k) {
    const ExprNode* n = steps_[k].node;
    const Interval a = steps_[k].a >= 0 ? values_[size_t(steps_[k].a)] : Interval{};
    const Interval b = steps_[k].b >= 0 ? values_[size_t(steps_[k].b)] : Interval{};
    Interval r;
    switch (n->op) {
      case Op::Const: r = {n->value, n->value}; break;
      case Op::Var: r = vars[static_cast<int>(n->var)]; break;
      case Op::Neg: r = {-a.hi, -a.lo}; break;
      case Op::Add: r = (a.bounded() && b.bounded()) ? widen(a.lo + b.lo, a.hi + b.hi) : kWhole; break;
      case Op::Sub: r = (a.bounded() && b.bounded()) ? widen(a.lo - b.hi, a.hi - b.lo) : kWhole; break;
      case Op::Mul: r = n->a == n->b ? integerPower(a, 2) : mul(a, b); break;
      case Op::Div: r = divide(a, b); break;
      case Op::Pow: r = power(a, *n->b, b); break;
      case Op::Call: r = call(n->fn, a); break;
      case Op::Spline: {  // the hull of the coefficients on the pieces a spans
        double lo, hi;
        r = a.bounded() && n->spline->range(a.lo, a.hi, &lo, &hi) ? widen(lo, hi) : kWhole;
        break;
      }
    }
    values_[k] = r;
  }
  return values_.back();
}

Interval enclose(const Expr& e, const Interval* vars) { return IntervalProgram(e).run(vars); }

}  // namespace pdesurf
