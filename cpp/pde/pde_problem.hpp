// The boundary-value problem of one PDE patch, per coordinate: an even-order operator
//   Σ_{k=0}^{n} alpha[k] ∂^{2(n-k)}/∂u^{2(n-k)} ∂^{2k}/∂v^{2k}
// (second order, seed 004 Eq. 1: alpha = {s, t}; fourth, seed 000 Eq. 2: {b, c, d}; sixth,
// seed 003 Eq. 1: {1, 3a², 3a⁴, a⁶}), a force f(u, v) on the right-hand side, and at u = 0
// and u = 1 the u-derivatives of orders 0..n-1 as sums of basis functions of v (seed 000
// Eqs. 3-4, seed 003 Eq. 2). Each coordinate has its own order: mixed order is a scene choice.
#pragma once
#include <array>
#include <vector>

#include "basis/vfunction.hpp"
#include "expr/expr.hpp"

namespace pdesurf {

struct VTerm {
  VFunction g;
  double coef = 1.0;
};
using VExpansion = std::vector<VTerm>;  // Σ coef · g(v)

// One force term: (Σ_k uPoly[k] u^k) · g(v) (seed 000 Eqs. 27-28, seed 004 Eq. 7).
struct ForceTerm {
  VFunction g;
  std::vector<double> uPoly;
};

// A force outside the families: an expression in u and v (only the general methods take it).
struct GeneralForce {
  std::string text;
  Expr f;
};

struct ComponentProblem {
  std::vector<double> alpha;     // n + 1 operator coefficients, alpha[0] != 0
  std::vector<ForceTerm> force;  // right-hand side, a sum of terms
  std::vector<GeneralForce> generalForce;  // more right-hand side, outside the families
  std::vector<VExpansion> left;  // left[i]  = ∂^i X/∂u^i at u = 0, i < n
  std::vector<VExpansion> right; // right[i] = ∂^i X/∂u^i at u = 1
};

struct PdeProblem {
  double v0 = 0.0, v1 = 0.0;
  // v closes on itself: the data are one loop (a fill's), periodic even where they have a
  // corner at v0, so an approximate method expands them in Fourier modes (the surface then
  // closes to rounding) rather than as open data (whose interior need not close).
  bool periodicV = false;
  std::array<ComponentProblem, 3> component;  // x, y, z
};

}  // namespace pdesurf
