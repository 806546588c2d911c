#include "surface/separable_surface.hpp"

namespace pdesurf {

double evalComponent(const SeparableSurface& s, int c, double u, double v, int du, int dv) {
  double sum = 0.0;
  for (const SeparableTerm& t : s.component[c]) sum += t.G.eval(u, du) * t.g.eval(v, dv);
  if (s.pointwise[c]) {
    const auto& pre = s.pointwisePartials[c];
    for (int q = 0; q < 6; ++q)  // built beforehand (X, X_u, X_v, X_uu, X_uv, X_vv)
      if (q < static_cast<int>(pre.size()) && kPartialOrders[q][0] == du && kPartialOrders[q][1] == dv) {
        const double vars[2] = {v, u};
        return sum + evaluate(*pre[q], vars);
      }
    Expr d = s.pointwise[c];
    for (int k = 0; k < du; ++k) d = derivative(d, ExprVar::U);
    for (int k = 0; k < dv; ++k) d = derivative(d, ExprVar::V);
    const double vars[2] = {v, u};
    sum += evaluate(*d, vars);
  }
  return sum;
}

Eigen::Vector3d evalPoint(const SeparableSurface& s, double u, double v, int du, int dv) {
  return {evalComponent(s, 0, u, v, du, dv), evalComponent(s, 1, u, v, du, dv), evalComponent(s, 2, u, v, du, dv)};
}

std::shared_ptr<const ExprProgram> pointwiseProgramOf(const SeparableSurface& s, int c) {
  if (!s.pointwise[c]) return nullptr;
  if (s.pointwisePrograms[c] && s.pointwisePartials[c].size() >= 6) return s.pointwisePrograms[c];
  const auto& pre = s.pointwisePartials[c];
  return std::make_shared<const ExprProgram>(pre.size() >= 6 ? pre : partialDerivatives(s.pointwise[c], true));
}

}  // namespace pdesurf
