// Bernstein polynomials on [0, 1] and the Gauss-Legendre rules that integrate their products
// exactly: a rule with q points is exact for polynomials of degree 2q - 1.
#pragma once
#include <vector>

namespace pdesurf {

// d^k/du^k B_i^n(u) for i = 0..n (zero for k > n).
std::vector<double> bernstein(int n, double u, int k = 0);

// Evaluation in Bernstein form, never through monomials (which cancel catastrophically at
// high degree). Every B_i^n(u) = C(n,i) u^i (1-u)^{n-i} is formed as a product of positive
// factors, so Σ b_i B_i^n(u) is accurate to a few ulps of Σ |b_i| B_i^n(u). Degrees up to
// kMaxBernsteinDegree.
constexpr int kMaxBernsteinDegree = 32;
// out[i] = B_i^n(u), i = 0..n.
void bernsteinValues(int n, double u, double* out);
// Coefficients of the k-th derivative of Σ b_i B_i^n in the Bernstein basis of degree n - k:
// n!/(n-k)! Δ^k b (forward differences). Empty when k > n.
std::vector<double> bernsteinDerivativeCoefs(const std::vector<double>& b, int k);
// Σ b_i B_i^n(u) with n = b.size() - 1.
double bernsteinSum(const double* b, int n, double u);
// d^k/du^k B_i^n(u) for one i.
double bernsteinBasis(int n, int i, double u, int k = 0);
// The same from low[] = B^{n-k}(u) (forward differences of e_i: at most k + 1 terms).
double bernsteinBasisFrom(const double* low, int n, int i, int k);

// B^n at every point of a grid, per degree, computed on first use: the terms of a Bézier
// patch share them, so a tabulation evaluates the basis once per point, not once per term.
class BernsteinOnGrid {
 public:
  BernsteinOnGrid(const double* t, int count) : t_(t), count_(count) {}
  int count() const { return count_; }
  // count × (n + 1) values, row i = B_0^n(t_i) .. B_n^n(t_i).
  const double* values(int n);

 private:
  const double* t_;
  int count_;
  std::vector<std::vector<double>> byDegree_;
};

struct GaussRule {
  std::vector<double> x, w;  // nodes in [0, 1], weights summing to 1
};
GaussRule gaussLegendre(int points);

}  // namespace pdesurf
