// Tabulated factors of a separable surface on a uniform (nu+1)×(nv+1) grid: each term's
// u-factor (value and first derivative) on the u-grid and v-factor (value and first
// derivative) on the v-grid, computed once. Combining them is then pure multiply-add:
//   X(u_i, v_j) = Σ_t G_t(u_i) g_t(v_j),  X_u = Σ G_t' g_t,  X_v = Σ G_t g_t'.
#pragma once
#include <vector>

#include "surface/separable_surface.hpp"

namespace pdesurf {

struct Tabulation {
  int nu = 0, nv = 0;
  std::vector<double> u, v;  // grid values, nu+1 and nv+1 entries
  // Per component c: T_c terms. uTab[c][(2t + k) * (nu+1) + i] = G_t^{(k)}(u_i), k = 0, 1
  // (rows along u, so combining a grid row is a contiguous, vectorisable loop);
  // vTab[c][j * 2T + 2t + k] = g_t^{(k)}(v_j).
  std::array<int, 3> terms{};
  std::array<std::vector<double>, 3> uTab, vTab;
  // Non-separable primary parts: value, ∂/∂u, ∂/∂v expressions per component (or nullptr).
  std::array<std::array<Expr, 3>, 3> pointwise;
};

// Throws Error(GridSize) outside 1..2048 per direction, Error(NonFinite) when a factor is not
// finite at a grid point.
Tabulation tabulate(const SeparableSurface& s, int nu, int nv);

constexpr int kMaxGrid = 2048;
void checkGrid(int nu, int nv);

}  // namespace pdesurf
