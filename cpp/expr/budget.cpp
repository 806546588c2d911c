#include "expr/budget.hpp"

#include "common/errors.hpp"

namespace pdesurf {

namespace {
thread_local ExprBudget* current = nullptr;
}

ExprBudget::ExprBudget(size_t limit, std::string what) : limit_(limit), what_(std::move(what)), outer_(current) { current = this; }

ExprBudget::~ExprBudget() { current = outer_; }

void ExprBudget::charge() {
  ExprBudget* b = current;
  if (b && ++b->used_ > b->limit_) b->refuse();
}

void ExprBudget::refuse() const {
  const std::string where = path_.empty() ? "" : path_ + ": ";
  throw Error(ErrorCode::TooLarge, where + what_ + " need more than " + std::to_string(limit_) +
                                       " expression nodes (docs/limits.md): simplify the expressions");
}

}  // namespace pdesurf
