// The u-ODE of one separable term. For a v-factor with g'' = sigma g, the operator
//   L = Σ_{k=0}^{n} alpha[k] ∂^{2(n-k)}/∂u^{2(n-k)} ∂^{2k}/∂v^{2k}
// (order 2n: n = 1 second, 2 fourth, 3 sixth order) maps G(u) g(v) to
//   (Σ_k alpha[k] sigma^k G^{(2(n-k))}(u)) g(v),
// so G solves a constant-coefficient ODE of order 2n with G^{(i)} given at u = 0 and u = 1
// for i < n. One mechanism handles every root structure: roots closer than one unit (the
// length of [0,1]) are grouped, and each group contributes the divided differences of
// r -> e^{r u} over its roots, which tend to u^j e^{r u} as roots merge (repeated roots)
// and stay well conditioned when they nearly merge.
//
// A force q(u) g(v) with q a polynomial of degree d is handled by the same mechanism rather
// than by adding a polynomial particular solution (which blows up like 1/sigma^n for slowly
// varying g and then cancels against the homogeneous part): G then solves the homogeneous
// ODE D^{d+1} L G = 0, whose roots are those of L plus d+1 zeros, and the d+1 extra
// conditions (L G)^{(i)}(0) = q^{(i)}(0), i <= d, make L G = q exactly.
#pragma once
#include <Eigen/Dense>
#include <vector>

#include "ode/u_factor.hpp"

namespace pdesurf {

// Boundary systems are small (2n + force degree + 1 <= 32): fixed-capacity matrices keep them
// off the heap.
constexpr int kMaxBoundarySystem = 32;
using BoundaryMatrix = Eigen::Matrix<cplx, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxBoundarySystem, kMaxBoundarySystem>;
using BoundaryVector = Eigen::Matrix<cplx, Eigen::Dynamic, 1, 0, kMaxBoundarySystem, 1>;
using BoundaryScale = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxBoundarySystem, 1>;

class EvenOdeBasis {
 public:
  // Throws Error(DegenerateOperator) when alpha[0] == 0 or a coefficient is not finite,
  // Error(Singular) when the two-point problem has no unique solution (resonance).
  // forceDegree: the degree of the force polynomials this basis will take (-1: no force).
  EvenOdeBasis(const std::vector<double>& alpha, double sigma, int forceDegree = -1);

  int halfOrder() const { return n_; }
  int forceDegree() const { return extra_ - 1; }
  const std::vector<cplx>& roots() const { return roots_; }
  // left[i] = G^{(i)}(0), right[i] = G^{(i)}(1), i < n; force: ascending coefficients of q,
  // at most forceDegree + 1 of them.
  UFactor solve(const double* left, const double* right, const std::vector<double>& force = {}) const;

 private:
  struct Cluster {
    cplx centre;
    double shift;
    std::vector<std::vector<cplx>> basis;  // q_j, ascending powers of (u - shift)
    bool augmented = false;                // holds some of the force's extra zero roots
  };
  int n_ = 0, extra_ = 0;
  std::vector<cplx> roots_;
  std::vector<Cluster> clusters_;
  BoundaryScale rowScale_, colScale_;
  Eigen::PartialPivLU<BoundaryMatrix> lu_;
};

// Roots of Σ_k alpha[k] sigma^k rho^{n-k} = 0 in r with r² = rho (2n values, complex).
std::vector<cplx> characteristicRoots(const std::vector<double>& alpha, double sigma);

}  // namespace pdesurf
