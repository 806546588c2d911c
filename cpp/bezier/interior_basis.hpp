// A well-conditioned basis of the free control points' space, for the solver's fallback
// (bezier_solver.cpp). With r fixed rings (membrane 1, thin plate 2) the free Bernstein
// functions B_r^n .. B_{n-r}^n span (u(1-u))^r · Π_{n-2r}; their Gram matrices grow
// ill-conditioned with n (the interior mass matrix: 8.7e8 per direction at n = 16, 7.6e17 for
// the tensor product, beyond double precision). The bubble-Legendre functions
//   ψ_k(u) = (u(1-u))^r P_k(2u - 1),   k = 0 .. n - 2r,
// span the same space with Gram matrices of modest condition.
#pragma once
#include <Eigen/Core>

namespace pdesurf {

// T, (n+1) × (n-2r+1): ψ_k = Σ_i T(i, k) B_i^n exactly up to rounding (rows i < r and
// i > n - r are zero). Built from the Bernstein form of P_k, (-1)^{k+i} C(k, i), times the
// bubble and degree-elevated to n: every step is exact or a convex combination.
Eigen::MatrixXd interiorToBernstein(int n, int r);

}  // namespace pdesurf
