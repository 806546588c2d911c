#include "basis/general_function.hpp"

#include "common/errors.hpp"
#include "common/text.hpp"
#include "expr/budget.hpp"
#include "expr/taylor.hpp"

namespace pdesurf {

namespace {
constexpr size_t kMaxDerivativeNodes = 200000;  // nodes built per derivative: a bound on symbolic swell
}

double GeneralFunction::eval(double v, int k) const {
  const double vars[2] = {v, 0.0};
  // Past the second derivative (normals and curvature need no more) Taylor arithmetic: its
  // cost grows with k², where each symbolic order multiplies the expression.
  if (k > 2) return derivativeAt(*derivs_.front(), ExprVar::V, vars, k);
  return evaluate(*derivativeExpr(k), vars);
}

void GeneralFunction::evalMany(const double* v, size_t n, int k, double* out) const {
  if (k > 2) {
    for (size_t i = 0; i < n; ++i) out[i] = eval(v[i], k);
    return;
  }
  if (static_cast<int>(programs_.size()) <= k) programs_.resize(k + 1);
  if (!programs_[k]) programs_[k] = std::make_shared<const ExprProgram>(std::vector<Expr>{derivativeExpr(k)});
  programs_[k]->run(v, nullptr, n, out);
}

void GeneralFunction::evalManyUpTo(const double* v, size_t n, int maxK, double* const* outs) const {
  if (maxK > 2) {
    for (int k = 0; k <= maxK; ++k) evalMany(v, n, k, outs[k]);
    return;
  }
  if (static_cast<int>(upTo_.size()) <= maxK) upTo_.resize(maxK + 1);
  if (!upTo_[maxK]) {
    std::vector<Expr> roots;
    for (int k = 0; k <= maxK; ++k) roots.push_back(derivativeExpr(k));
    upTo_[maxK] = std::make_shared<const ExprProgram>(roots);
  }
  upTo_[maxK]->runAll(v, nullptr, n, outs);
}

const Expr& GeneralFunction::derivativeExpr(int k) const {
  while (static_cast<int>(derivs_.size()) <= k) {
    const std::string what = "'" + clipText(text_, 200) + "': its derivative of order " + std::to_string(derivs_.size()) + " would";
    ExprBudget budget(kMaxDerivativeNodes, what);  // stops the build at the first node over it
    derivs_.push_back(derivative(derivs_.back(), ExprVar::V));
  }
  return derivs_[k];
}

}  // namespace pdesurf
