// Exact solution of a PdeProblem whose boundary functions all lie in the basis families:
// each eigen-family term (cos, sin, exp, cosh, sinh of w·v) gets its own u-ODE
// (ode/even_ode.hpp); polynomial terms in v couple into a triangular system of polynomial
// ODEs in u (pde/poly_in_v.hpp). The result satisfies the boundary conditions exactly up to
// rounding and the PDE identically.
#pragma once
#include "pde/pde_problem.hpp"
#include "surface/separable_surface.hpp"

namespace pdesurf {

class BasisCache;

// Throws Error (DegenerateOperator, Singular, NonFinite, InvalidField) naming the component
// and term at fault.
// `cache` (optional) keeps the ODE bases between solves.
SeparableSurface solveClosedForm(const PdeProblem& problem, BasisCache* cache = nullptr);

}  // namespace pdesurf
