#include "basis/general_function.hpp"

#include <list>

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
  if (derivativeExpr(k)->treeSize <= kTreeWalkMax) return evaluate(*derivativeExpr(k), vars);
  double out = 0.0;
  evalMany(&v, 1, k, &out);
  return out;
}

void GeneralFunction::evalMany(const double* v, size_t n, int k, double* out) const {
  if (k > 2) {
    for (size_t i = 0; i < n; ++i) out[i] = eval(v[i], k);
    return;
  }
  // The lower orders come with it: they are the derivative's own subexpressions.
  std::vector<double> lower(static_cast<size_t>(k) * n);
  double* outs[3] = {nullptr, nullptr, nullptr};
  for (int r = 0; r < k; ++r) outs[r] = lower.data() + static_cast<size_t>(r) * n;  // none for k = 0 (no offset from null)
  outs[k] = out;
  upTo(k).runAll(v, nullptr, n, outs);
}

void GeneralFunction::evalManyUpTo(const double* v, size_t n, int maxK, double* const* outs) const {
  if (maxK > 2) {
    for (int k = 0; k <= maxK; ++k) evalMany(v, n, k, outs[k]);
    return;
  }
  upTo(maxK).runAll(v, nullptr, n, outs);
}

namespace {

// Programs compiled before, by expression: expressions are interned (expr.cpp), so a function
// that did not change between two solves of an edited scene is the same node while the last
// solve holds it (the page's module keeps it for the report) — a slider step parses the whole
// scene again, and most of its functions (a wing's profile) are as they were. Per thread (the
// CLI fits on several), the most recent kCompiledKept, each holding its expressions alive so
// that no other node can take their address.
struct Compiled {
  int maxK;
  std::vector<Expr> derivs;  // derivs[0] is the key
  std::shared_ptr<const ExprProgram> program;
};
constexpr size_t kCompiledKept = 256;

std::list<Compiled>& compiledCache() {
  thread_local std::list<Compiled> cache;  // most recent first
  return cache;
}

}  // namespace

const ExprProgram& GeneralFunction::upTo(int maxK) const {
  if (static_cast<int>(upTo_.size()) <= maxK) upTo_.resize(maxK + 1);
  if (upTo_[maxK]) return *upTo_[maxK];
  std::list<Compiled>& cache = compiledCache();
  for (auto it = cache.begin(); it != cache.end(); ++it)
    if (it->maxK == maxK && it->derivs.front() == derivs_.front()) {
      cache.splice(cache.begin(), cache, it);
      if (derivs_.size() < it->derivs.size()) derivs_ = it->derivs;  // the same derivatives, not formed again
      return *(upTo_[maxK] = it->program);
    }
  std::vector<Expr> roots;
  for (int k = 0; k <= maxK; ++k) roots.push_back(derivativeExpr(k));
  upTo_[maxK] = std::make_shared<const ExprProgram>(roots);
  cache.push_front({maxK, roots, upTo_[maxK]});
  if (cache.size() > kCompiledKept) cache.pop_back();
  return *upTo_[maxK];
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
