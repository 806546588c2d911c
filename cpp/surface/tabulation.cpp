#include "surface/tabulation.hpp"

#include <cmath>
#include <string>

#include "common/errors.hpp"

namespace pdesurf {

void checkGrid(int nu, int nv) {
  if (nu < 1 || nv < 1 || nu > kMaxGrid || nv > kMaxGrid)
    throw Error(ErrorCode::GridSize, "grid " + std::to_string(nu) + "x" + std::to_string(nv) +
                                         " is outside 1x1 .. " + std::to_string(kMaxGrid) + "x" + std::to_string(kMaxGrid));
}

Tabulation tabulate(const SeparableSurface& s, int nu, int nv) {
  checkGrid(nu, nv);
  Tabulation t;
  t.nu = nu;
  t.nv = nv;
  t.u.resize(nu + 1);
  t.v.resize(nv + 1);
  // Both ends exactly, so boundary rows reproduce the boundary conditions.
  for (int i = 0; i <= nu; ++i) t.u[i] = i == nu ? s.u1 : s.u0 + (s.u1 - s.u0) * i / nu;
  for (int j = 0; j <= nv; ++j) t.v[j] = j == nv ? s.v1 : s.v0 + (s.v1 - s.v0) * j / nv;
  static const char* axis[3] = {"x", "y", "z"};
  for (int c = 0; c < 3; ++c) {
    const auto& terms = s.component[c];
    const int T = static_cast<int>(terms.size());
    t.terms[c] = T;
    t.uTab[c].assign(static_cast<size_t>(nu + 1) * 2 * T, 0.0);
    t.vTab[c].assign(static_cast<size_t>(nv + 1) * 2 * T, 0.0);
    for (int k = 0; k < T; ++k) {
      double* uk = t.uTab[c].data() + static_cast<size_t>(2 * k) * (nu + 1);
      terms[k].G.tabulate(t.u.data(), nu + 1, 1, uk);
      bool finite = true;
      for (int i = 0; i < 2 * (nu + 1); ++i) finite = finite && std::isfinite(uk[i]);
      for (int j = 0; j <= nv; ++j) {
        const double g0 = terms[k].g.eval(t.v[j], 0), g1 = terms[k].g.eval(t.v[j], 1);
        t.vTab[c][j * 2 * T + 2 * k] = g0;
        t.vTab[c][j * 2 * T + 2 * k + 1] = g1;
        finite = finite && std::isfinite(g0) && std::isfinite(g1);
      }
      if (!finite)
        throw Error(ErrorCode::NonFinite, std::string("component ") + axis[c] + ": term " + describeFunction(terms[k].g) +
                                              " is not finite on the grid (v from " + std::to_string(s.v0) + " to " + std::to_string(s.v1) + ")");
    }
  }
  for (int c = 0; c < 3; ++c)
    if (s.pointwise[c])
      t.pointwise[c] = {s.pointwise[c], derivative(s.pointwise[c], ExprVar::U), derivative(s.pointwise[c], ExprVar::V)};
  return t;
}

}  // namespace pdesurf
