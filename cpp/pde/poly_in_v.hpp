// Boundary data polynomial in v. With X = Σ_m G_m(u) v^m the operator gives, per power m,
//   alpha[0] G_m^{(2n)} = f_m(u) - Σ_{j>=1} alpha[j] (m+2j)!/m! G_{m+2j}^{(2n-2j)},
// a triangular system solved from the top power down: each G_m is a particular polynomial
// (integrate the right side 2n times) plus the Hermite polynomial of degree 2n-1 that meets
// the boundary conditions. Everything stays polynomial, so the solution is exact.
#pragma once
#include <vector>

namespace pdesurf {

// data[m][end][i] = the coefficient of v^m in ∂^i X/∂u^i at u = end (end 0 or 1, i < n).
// force[m] = f_m, the force's coefficient of v^m as ascending coefficients in u (may be empty).
// Returns G_m as ascending coefficients in u, one per power m.
std::vector<std::vector<double>> solvePolyInV(const std::vector<double>& alpha,
                                              const std::vector<std::vector<std::vector<double>>>& data,
                                              const std::vector<std::vector<double>>& force);

}  // namespace pdesurf
