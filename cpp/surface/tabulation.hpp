// Tabulated factors of a separable surface on a uniform (nu+1)×(nv+1) grid: each term's
// u-factor on the u-grid and v-factor on the v-grid with their derivatives up to
// maxDerivative (1, or 2 for curvature), computed once. Combining them is then multiply-add:
//   X(u_i, v_j) = Σ_t G_t(u_i) g_t(v_j),  X_u = Σ G_t' g_t,  X_v = Σ G_t g_t',
//   X_uu = Σ G_t'' g_t,  X_uv = Σ G_t' g_t',  X_vv = Σ G_t g_t''.
#pragma once
#include <vector>

#include "common/limits.hpp"
#include "expr/program.hpp"
#include "surface/separable_surface.hpp"

namespace pdesurf {

struct Tabulation {
  int nu = 0, nv = 0;
  int depth = 2;  // derivatives 0 .. depth-1 are tabulated
  std::vector<double> u, v;  // grid values, nu+1 and nv+1 entries
  // Per component c: T_c terms. uTab[c][(depth·t + k) * (nu+1) + i] = G_t^{(k)}(u_i) (rows
  // along u, so combining a grid row is a contiguous, vectorisable loop);
  // vTab[c][j * depth·T + depth·t + k] = g_t^{(k)}(v_j).
  std::array<int, 3> terms{};
  std::array<std::vector<double>, 3> uTab, vTab;
  // Non-separable primary parts per component (or nullptr): the expression and its partial
  // derivatives, in the order X, X_u, X_v, X_uu, X_uv, X_vv (the first 3 or all 6).
  std::array<std::vector<Expr>, 3> pointwise;
  // The same compiled into one program per component (outputs in that order), run once per
  // grid row over all its points.
  std::array<std::shared_ptr<const ExprProgram>, 3> pointwiseProgram;
};

// Throws Error(GridSize) outside 1..2048 per direction, Error(NonFinite) when a factor is not
// finite at a grid point. maxDerivative: 1 or 2.
Tabulation tabulate(const SeparableSurface& s, int nu, int nv, int maxDerivative = 1);
// The same at given parameters (any order, any spacing: quadrature nodes), 1 to 2049 each.
Tabulation tabulateAt(const SeparableSurface& s, std::vector<double> u, std::vector<double> v, int maxDerivative = 1);

constexpr int kMaxGrid = limits::kGrid;
void checkGrid(int nu, int nv);

}  // namespace pdesurf
