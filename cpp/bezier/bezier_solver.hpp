// The seed 002 solver. The energy is a quadratic form in the control points' coordinates,
//   E(x) = ½ xᵀ Q x - (G ŝ)ᵀ x + const,
// with x all control coordinates (3 per point: the normal term couples x, y and z) and ŝ the
// initial surface's. Q depends only on the degree, the energy, the normal field, λ and γ: the
// solver assembles it and factors its free-free block once, so a drag of a control point of
// S (which changes only the right-hand side) costs a back-substitution
// (geometry-central's pattern: a one-off function and a stateful solver).
//
// Exactness: the integrals are Gauss-Legendre products in u and v with enough points for
// their polynomial degree (fairness: degree ≤ 2n in u, n + 1 points; normal and data terms:
// degree ≤ 2(n - 1) + 2 n1 resp. 2n, n + n1 points), hence exact up to rounding. A discrete
// normal field replaces the normal and data integrals by trapezoidal sums over its samples.
#pragma once
#include <Eigen/Core>
#include <Eigen/Cholesky>
#include <vector>

#include "bezier/bezier_problem.hpp"
#include "surface/separable_surface.hpp"

namespace pdesurf {

using ControlNet = std::vector<Eigen::Vector3d>;

class BezierSolver {
 public:
  // Throws Error(InvalidField) for a degree too low for the energy, negative λ or γ, a
  // malformed normal field; Error(NonFinite) for non-finite input; Error(Singular) when the
  // free-free block is not positive definite to working precision, in the Bernstein basis and
  // in the well-conditioned interior basis (interior_basis.hpp) alike.
  explicit BezierSolver(const BezierProblem& shape);

  // The minimiser for this initial surface (its boundary rings are kept bit for bit).
  ControlNet solve(const ControlNet& initial) const;
  // E(R) for a net R and initial surface S (the same quadrature as the solve).
  double energy(const ControlNet& net, const ControlNet& initial) const;
  // ∫ (R_u·N)² + (R_v·N)² (or its sum over the samples, with the λ weights): the normal misfit.
  double normalMisfit(const ControlNet& net) const;

  const BezierProblem& shape() const { return shape_; }

 private:
  BezierProblem shape_;
  Eigen::MatrixXd Q_, G_, normal_;  // 3K×3K
  std::vector<int> free_, fixed_;   // coordinate indices
  Eigen::MatrixXd Qfx_, Gf_;
  Eigen::MatrixXd Tfree_;  // empty, or the fallback's basis: x_free = Tfree_ y (ldlt_ factors y's matrix)
  Eigen::LDLT<Eigen::MatrixXd> ldlt_;

  void factorInInteriorBasis();
};

// One-off: S from the problem.
ControlNet solveBezier(const BezierProblem& p);

// The Bézier surface as separable terms (monomials in u times powers of v), for tessellation.
SeparableSurface bezierToSeparable(int n, int m, const ControlNet& net);

// Checks a problem; throws the errors listed for BezierSolver.
void validateBezierProblem(const BezierProblem& p);

}  // namespace pdesurf
