// The boundary data of a PDE patch imposed exactly on an approximate solution (seed 000's own
// device, Eq. 10: a Hermite lift in u carries the boundary functions). A method that
// approximates the boundary functions (modal: Fourier modes or a Chebyshev interpolant) meets
// its approximations, not the data; a blend is judged at its joins, so the approximation may
// touch the interior only. For each coordinate of order 2n, with h_s the Hermite polynomials
// of degree 2n-1 (h_s carries the derivative i at the end e of slot s = e*n + i):
//   X  <-  X - Σ_s h_s(u) ∂^i_u X(e, v) + Σ_s h_s(u) data_s(v)
// The first sum removes every term's own boundary values (a polynomial piece added to its
// u-factor, so no term is added), the second adds the data as given (general functions
// evaluated exactly). The change is L-small where the approximation is good; its size is the
// PDE residual (interiorResidual, methods/measures.hpp), reported, never the joins.
#pragma once
#include <vector>

#include "pde/pde_problem.hpp"
#include "surface/separable_surface.hpp"

namespace pdesurf {

// Hermite basis of degree 2n-1 on [0, 1], ascending powers: h[s] has unit slot s = end*n + i.
std::vector<std::vector<double>> hermiteBasis(int n);

// Decay rates of the lift's slots at u = 0 and at u = 1 (0: the Hermite polynomials h_s).
// With atU0 = λ > 0 the u = 0 end's slots are carried by e^{-λu} p_i(u) (p_i of degree n-1,
// unit derivative i at u = 0), corrected at u = 1 by the Hermite basis; atU1 likewise from
// u = 1 inward. What the lift adds there is the approximation's remainder, the data's modes
// beyond N; a mode k of an even-order operator with these coefficients decays like e^{-ku}
// (times powers of u), so a decay of N + 1 carries the remainder as the true solution does its
// slowest omitted mode (the modal method passes 2(N + 1): measured, it leaves less at the
// sharpest corners). A loop with corners (a fill's, a lens section's, a trailing edge's) has a
// kink at each as its remainder, which h_s would carry unchanged along the corner's line across
// the patch (a crease); this lets it die out within ~1/N of the edge that has it.
struct LiftDecay {
  double atU0 = 0.0, atU1 = 0.0;
};
void imposeBoundaryData(SeparableSurface& s, const PdeProblem& p, const LiftDecay& decay = {});

}  // namespace pdesurf
