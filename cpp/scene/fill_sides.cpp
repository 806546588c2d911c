#include "scene/fill_sides.hpp"

#include <cmath>

#include "common/errors.hpp"
#include "scene/patch_graph.hpp"

namespace pdesurf {

Eigen::Vector3d valueAt(const Vec3Expr& e, double v) {
  const double vars[2] = {v, 0.0};
  return {evaluate(*e[0], vars), evaluate(*e[1], vars), evaluate(*e[2], vars)};
}

FillSide fillSideOf(const Patch& fill, size_t k, const SolvedLookup& solved, int depth) {
  const bool tangency = depth >= 1;
  const LoopBorder& b = fill.fill.borders[k];
  const size_t n = fill.fill.borders.size();
  const SolvedPatch& source = solved(b.patch);
  EdgeExprs e = solvedEdge(source, b.edge, depth);
  FillSide s;
  const auto part = fillSideRange(k, n);
  s.v0 = part[0], s.v1 = part[1];
  s.name = "'" + b.patch + "' " + edgeName(*source.patch, b.edge);
  // The edge's parameter runs from `from` to `to` (or back) as σ runs 0..1, with w = (v - v0) /
  // (v1 - v0) and σ = w - sin(2πw) / 2π, whose speed vanishes at both ends: at the loop's
  // corners, where the sides' tangents and cross derivatives turn, the loop's position and
  // cross derivative are then C1 in v (both one-sided v-derivatives are 0), so the fill's
  // series does not ring there. A single closed border has no corner: σ = w.
  const double a = b.reverse ? b.to : b.from, span = (b.reverse ? b.from : b.to) - a;
  const Expr w = divide(subtract(variable(ExprVar::V), constant(s.v0)), constant(s.v1 - s.v0));
  s.sigma = n == 1 ? w : subtract(w, multiply(constant(kFillEase / (2 * M_PI)), call(ExprFn::Sin, multiply(constant(2 * M_PI), w))));
  const Expr param = add(constant(a), multiply(constant(span), s.sigma));
  for (int c = 0; c < 3; ++c) {
    s.X[c] = substitute(e.X[c], ExprVar::V, param);
    s.D[c] = tangency ? substitute(e.out[c], ExprVar::V, param) : constant(0.0);
    s.T[c] = tangency ? multiply(constant(span), substitute(derivative(e.X[c], ExprVar::V), ExprVar::V, param)) : constant(0.0);
    if (depth < 2) continue;
    s.Xss[c] = multiply(constant(span * span), substitute(derivative(derivative(e.X[c], ExprVar::V), ExprVar::V), ExprVar::V, param));
    s.Xsw[c] = multiply(constant(span), substitute(derivative(e.out[c], ExprVar::V), ExprVar::V, param));
    s.Xww[c] = substitute(e.outOut[c], ExprVar::V, param);
  }
  for (int i = 0; i <= kPerSide; ++i) {
    const double v = s.v0 + (s.v1 - s.v0) * i / kPerSide;
    s.x.push_back(valueAt(s.X, v));
    s.d.push_back(valueAt(s.D, v));
    bool finite = s.x.back().allFinite() && s.d.back().allFinite();
    if (depth >= 1) {
      s.t.push_back(valueAt(s.T, v));
      finite = finite && s.t.back().allFinite();
    }
    if (depth >= 2) {
      s.dd.push_back(valueAt(s.Xww, v));
      finite = finite && s.dd.back().allFinite() && valueAt(s.Xss, v).allFinite() && valueAt(s.Xsw, v).allFinite();
    }
    if (!finite) throw Error(ErrorCode::NonFinite, b.path + ": " + s.name + " is not finite at v = " + shortNumber(v));
  }
  return s;
}

}  // namespace pdesurf
