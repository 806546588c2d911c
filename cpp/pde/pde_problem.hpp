// The boundary-value problem of one PDE patch, per coordinate: an even-order operator
//   Σ_{k=0}^{n} alpha[k] ∂^{2(n-k)}/∂u^{2(n-k)} ∂^{2k}/∂v^{2k}
// (fourth order, seed 000 Eq. 2: alpha = {b, c, d}) and, at u = 0 and u = 1, the u-derivatives
// of orders 0..n-1 as sums of basis functions of v (seed 000 Eqs. 3-4).
#pragma once
#include <array>
#include <vector>

#include "basis/vfunction.hpp"

namespace pdesurf {

struct VTerm {
  VFunction g;
  double coef = 1.0;
};
using VExpansion = std::vector<VTerm>;  // Σ coef · g(v)

struct ComponentProblem {
  std::vector<double> alpha;     // n + 1 operator coefficients, alpha[0] != 0
  std::vector<VExpansion> left;  // left[i]  = ∂^i X/∂u^i at u = 0, i < n
  std::vector<VExpansion> right; // right[i] = ∂^i X/∂u^i at u = 1
};

struct PdeProblem {
  double v0 = 0.0, v1 = 0.0;
  std::array<ComponentProblem, 3> component;  // x, y, z
};

}  // namespace pdesurf
