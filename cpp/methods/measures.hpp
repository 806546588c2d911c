// How far a solution is from another and from its own problem.
#pragma once
#include "pde/pde_problem.hpp"
#include "surface/separable_surface.hpp"

namespace pdesurf {

// Seed 000 Eq. 24: the mean over an Iu × Jv grid of |X_ref - X| / |X_ref|, with
// u_i = i/(Iu-1), v_j = v0 + (v1-v0) j/(Jv-1) (both ends included: the paper says only
// "uniformly distributed points within the blending surface").
double relativeError(const SeparableSurface& reference, const SeparableSurface& other, int Iu, int Jv);

// The largest boundary-condition error of any component, end and derivative order over 201
// v-samples, relative to max(1, |prescribed value|).
double boundaryConditionError(const PdeProblem& p, const SeparableSurface& s, int samples = 200);

// The largest |L X - f| over an interior 21×21 grid, relative to max(1, Σ |parts|) at each point.
double pdeResidual(const PdeProblem& p, const SeparableSurface& s);

// How well a solved patch satisfies its PDE inside, as `pdesurf check` reports it: the largest
// |L X - f| over the interior points of a grid × grid lattice, absolute and relative to the
// largest Σ_k |α_k ∂^{2(n-k)}_u ∂^{2k}_v X| there (the size of what cancels: digits lost,
// whatever the scene's scale). Every method auto picks meets the boundary data exactly, so the
// interior error e = X - X* has zero boundary data and L e = the residual.
struct PdeResidual {
  double absolute = 0.0, relative = 0.0;
  double u = 0.0, v = 0.0;  // where the relative figure is largest
};
PdeResidual interiorResidual(const PdeProblem& p, const SeparableSurface& s, int grid = 16);

}  // namespace pdesurf
