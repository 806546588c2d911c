#include "scene/fill_sides.hpp"

#include <cmath>

#include "common/errors.hpp"
#include "expr/program.hpp"
#include "scene/patch_graph.hpp"

namespace pdesurf {

Eigen::Vector3d valueAt(const Vec3Expr& e, double v) {
  const double vars[2] = {v, 0.0};
  return {evaluate(*e[0], vars), evaluate(*e[1], vars), evaluate(*e[2], vars)};
}

FillSide fillSideOf(const Patch& fill, size_t k, const SolvedLookup& solved, int depth) {
  const bool tangency = depth >= 1;
  const LoopBorder& b = fill.fill().borders[k];
  const size_t n = fill.fill().borders.size();
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
  // The samples: every expression the depth asks for, in one program run over all the points
  // (the sides share their source's subexpressions; a tree walk per point and expression
  // evaluated them again and again).
  std::vector<Expr> roots(s.X.begin(), s.X.end());
  if (depth >= 1) roots.insert(roots.end(), s.D.begin(), s.D.end()), roots.insert(roots.end(), s.T.begin(), s.T.end());
  if (depth >= 2)
    for (const Vec3Expr* e : {&s.Xww, &s.Xss, &s.Xsw}) roots.insert(roots.end(), e->begin(), e->end());
  const size_t m = kPerSide + 1;
  std::vector<double> vs(m), values(roots.size() * m);
  std::vector<double*> outs(roots.size());
  for (size_t i = 0; i < m; ++i) vs[i] = s.v0 + (s.v1 - s.v0) * static_cast<double>(i) / kPerSide;
  for (size_t r = 0; r < roots.size(); ++r) outs[r] = values.data() + r * m;
  ExprProgram(roots).runAll(vs.data(), nullptr, m, outs.data());
  const auto at = [&](size_t r, size_t i) { return Eigen::Vector3d(outs[r][i], outs[r + 1][i], outs[r + 2][i]); };
  for (size_t i = 0; i < m; ++i) {
    s.x.push_back(at(0, i));
    s.d.push_back(depth >= 1 ? at(3, i) : Eigen::Vector3d::Zero());
    if (depth >= 1) s.t.push_back(at(6, i));
    if (depth >= 2) s.dd.push_back(at(9, i));
    bool finite = true;
    for (size_t r = 0; r < roots.size(); ++r) finite = finite && std::isfinite(outs[r][i]);
    if (!finite) throw Error(ErrorCode::NonFinite, b.path + ": " + s.name + " is not finite at v = " + shortNumber(vs[i]));
  }
  return s;
}

}  // namespace pdesurf
