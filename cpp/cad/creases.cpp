#include "cad/creases.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "basis/general_function.hpp"

namespace pdesurf {
namespace {

// Arguments of abs and sign that depend on v only, each distinct node once.
void collectKinkArguments(const Expr& root, std::unordered_set<const ExprNode*>& seen, std::vector<Expr>& out) {
  std::vector<const Expr*> stack{&root};
  while (!stack.empty()) {
    const Expr& e = *stack.back();
    stack.pop_back();
    if (!e || !seen.insert(e.get()).second) continue;
    if (e->op == ExprNode::Op::Call && (e->fn == ExprFn::Abs || e->fn == ExprFn::Sign) && e->a->vars == 1) out.push_back(e->a);
    stack.push_back(&e->a);
    stack.push_back(&e->b);
  }
}

// Zeros of f on (a, b) by sign changes on a fine grid, then bisection to the last bit.
void zeros(const Expr& f, double a, double b, std::vector<double>& out) {
  constexpr int kSamples = 4096;
  auto at = [&](double v) {
    const double vars[2] = {v, 0.0};
    return evaluate(*f, vars);
  };
  double x0 = a, f0 = at(a);
  for (int k = 1; k <= kSamples; ++k) {
    const double x1 = k == kSamples ? b : a + (b - a) * k / kSamples, f1 = at(x1);
    if (std::isfinite(f0) && std::isfinite(f1) && (f0 == 0 || (f0 < 0) != (f1 < 0))) {
      double lo = x0, hi = x1, flo = f0;
      if (f0 == 0) {
        hi = lo;
      } else {
        for (int it = 0; it < 80 && hi - lo > 0; ++it) {
          const double mid = 0.5 * (lo + hi), fm = at(mid);
          if (mid <= lo || mid >= hi) break;
          if ((fm < 0) == (flo < 0) && fm != 0) lo = mid, flo = fm;
          else hi = mid;
        }
      }
      out.push_back(hi);
    }
    x0 = x1, f0 = f1;
  }
}

}  // namespace

std::vector<double> findCreases(const SeparableSurface& s, bool* kinkAtEnds) {
  std::unordered_set<const ExprNode*> seen;
  std::vector<Expr> arguments;
  for (const auto& terms : s.component)
    for (const SeparableTerm& t : terms)
      if (t.g.family == Family::General) collectKinkArguments(t.g.general->expr(), seen, arguments);
  std::vector<double> found;
  for (const Expr& f : arguments) zeros(f, s.v0, s.v1, found);
  std::sort(found.begin(), found.end());
  // Kinks closer than this are one corner (a scene may pin a corner's value with two sign()s
  // 1e-9 apart): a knot span that short would make the spline's derivative bounds meaningless.
  const double eps = 1e-6 * (s.v1 - s.v0);
  std::vector<double> out;
  if (kinkAtEnds) *kinkAtEnds = false;
  for (double v : found) {
    if (v <= s.v0 + eps || v >= s.v1 - eps) {  // the ends are knots already
      if (kinkAtEnds) *kinkAtEnds = true;
      continue;
    }
    if (!out.empty() && v - out.back() <= eps) continue;
    out.push_back(v);
    if (int(out.size()) == kMaxCreases) break;
  }
  return out;
}

}  // namespace pdesurf
