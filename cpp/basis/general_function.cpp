#include "basis/general_function.hpp"

#include "common/errors.hpp"
#include "common/text.hpp"
#include "expr/taylor.hpp"

namespace pdesurf {

namespace {
constexpr size_t kMaxDerivativeNodes = 200000;  // a bound on symbolic swell
}

double GeneralFunction::eval(double v, int k) const {
  const double vars[2] = {v, 0.0};
  // Past the second derivative (normals and curvature need no more) Taylor arithmetic: its
  // cost grows with k², where each symbolic order multiplies the expression.
  if (k > 2) return derivativeAt(*derivs_.front(), ExprVar::V, vars, k);
  while (static_cast<int>(derivs_.size()) <= k) {
    Expr next = derivative(derivs_.back(), ExprVar::V);
    if (nodeCount(next) > kMaxDerivativeNodes)
      throw Error(ErrorCode::TooLarge, "'" + clipText(text_, 200) + "' is too complex to differentiate " + std::to_string(k) + " times");
    derivs_.push_back(std::move(next));
  }
  return evaluate(*derivs_[k], vars);
}

}  // namespace pdesurf
