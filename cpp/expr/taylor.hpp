// Derivatives of an expression at a point by Taylor arithmetic (automatic differentiation in
// truncated power series): every node becomes its Taylor coefficients up to `order`, combined
// by the usual recurrences (Cauchy products, exp/log/sin/cos/pow by their ODEs). The cost is
// O(order² · distinct nodes) per point, whatever the order, where symbolic derivatives swell
// with each order (a product rule per level). For the high v-derivatives that only a few
// points need: the end matching of the open-data approximation (methods/approximate.hpp) and
// the PDE residual (interiorResidual, methods/measures.hpp).
#pragma once
#include <vector>

#include "expr/expr.hpp"

namespace pdesurf {

// out[k] = (1/k!) d^k e / d var^k at the point vars (vars[0] = v, vars[1] = u), k = 0..order.
// NaN or inf where a coefficient is not finite (a pole, abs or sqrt at 0); callers check.
std::vector<double> taylorCoefficients(const ExprNode& e, ExprVar var, const double* vars, int order);

// d^k e / d var^k at vars.
double derivativeAt(const ExprNode& e, ExprVar var, const double* vars, int k);

}  // namespace pdesurf
