// Bernstein polynomials on [0, 1] and the Gauss-Legendre rules that integrate their products
// exactly: a rule with q points is exact for polynomials of degree 2q - 1.
#pragma once
#include <vector>

namespace pdesurf {

// d^k/du^k B_i^n(u) for i = 0..n (zero for k > n).
std::vector<double> bernstein(int n, double u, int k = 0);

// B_i^n(u) as ascending monomial coefficients, per i: out[i][a] = coefficient of u^a.
std::vector<std::vector<double>> bernsteinMonomials(int n);

struct GaussRule {
  std::vector<double> x, w;  // nodes in [0, 1], weights summing to 1
};
GaussRule gaussLegendre(int points);

}  // namespace pdesurf
