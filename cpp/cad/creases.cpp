#include "cad/creases.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "basis/general_function.hpp"
#include "expr/program.hpp"
#include "expr/spline.hpp"

namespace pdesurf {
namespace {

// Arguments of abs and sign that depend on v only, each distinct node once; a B-spline
// function of v contributes its argument minus each knot where it is only C0.
void collectKinkArguments(const Expr& root, std::unordered_set<const ExprNode*>& seen, std::vector<Expr>& out) {
  std::vector<const Expr*> stack{&root};
  while (!stack.empty()) {
    const Expr& e = *stack.back();
    stack.pop_back();
    if (!e || !seen.insert(e.get()).second) continue;
    if (e->op == ExprNode::Op::Call && (e->fn == ExprFn::Abs || e->fn == ExprFn::Sign) && e->a->vars == 1) out.push_back(e->a);
    if (e->op == ExprNode::Op::Spline && e->a->vars == 1)
      for (double knot : e->spline->kinks()) out.push_back(subtract(e->a, constant(knot)));
    stack.push_back(&e->a);
    stack.push_back(&e->b);
  }
}

// Zeros of each argument on (a, b): sign changes on a fine grid (all arguments in one
// compiled pass), then bisection to the last bit.
void zeros(const std::vector<Expr>& args, double a, double b, std::vector<double>& out) {
  constexpr int kSamples = 2048;
  std::vector<double> v(kSamples + 1);
  for (int k = 0; k <= kSamples; ++k) v[size_t(k)] = k == kSamples ? b : a + (b - a) * k / kSamples;
  std::vector<std::vector<double>> values(args.size(), std::vector<double>(v.size()));
  std::vector<double*> outs;
  for (auto& row : values) outs.push_back(row.data());
  ExprProgram(args).runAll(v.data(), nullptr, v.size(), outs.data());
  for (size_t r = 0; r < args.size(); ++r) {
    auto at = [&](double x) {
      const double vars[2] = {x, 0.0};
      return evaluate(*args[r], vars);
    };
    const std::vector<double>& f = values[r];
    for (size_t k = 1; k < v.size(); ++k) {
      const double f0 = f[k - 1], f1 = f[k];
      if (!std::isfinite(f0) || !std::isfinite(f1) || !(f0 == 0 || (f0 < 0) != (f1 < 0))) continue;
      double lo = v[k - 1], hi = f0 == 0 ? lo : v[k], flo = f0;
      for (int it = 0; it < 80 && hi > lo; ++it) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        const double fm = at(mid);
        if ((fm < 0) == (flo < 0) && fm != 0) lo = mid, flo = fm;
        else hi = mid;
      }
      out.push_back(hi);
    }
  }
}

}  // namespace

std::vector<double> findCreases(const SeparableSurface& s, bool* kinkAtEnds) {
  std::unordered_set<const ExprNode*> seen;
  std::vector<Expr> arguments;
  for (const auto& terms : s.component)
    for (const SeparableTerm& t : terms)
      if (t.g.family == Family::General) collectKinkArguments(t.g.general->expr(), seen, arguments);
  for (const Expr& e : s.pointwise)  // a B-spline surface's v-curves live in its pointwise part
    if (e) collectKinkArguments(e, seen, arguments);
  std::vector<double> found;
  if (!arguments.empty()) zeros(arguments, s.v0, s.v1, found);
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
