// How well a solved PDE patch satisfies its PDE inside: the residual L X - f at the interior
// points of a grid, per coordinate. The boundary data are met exactly by every method auto
// picks (methods/boundary_lift.hpp); the error inside e = X - X* then has zero boundary data
// and L e = residual, so the residual bounds the interior error up to the inverse operator's
// norm. Relative: divided by the largest Σ_k |α_k ∂^{2(n-k)}_u ∂^{2k}_v X| on the grid (the
// size of what cancels), so it reads as digits lost, whatever the scene's scale.
#pragma once
#include "pde/pde_problem.hpp"
#include "surface/separable_surface.hpp"

namespace pdesurf {

struct PdeResidual {
  double absolute = 0.0;  // largest |L X - f|
  double relative = 0.0;  // absolute / largest Σ_k |α_k ∂ X|
  double u = 0.0, v = 0.0;  // where the relative figure is largest
};

// On the (grid-1)² interior points of a grid × grid lattice over [0, 1] × [v0, v1].
PdeResidual pdeResidual(const SeparableSurface& s, const PdeProblem& p, int grid = 16);

}  // namespace pdesurf
