// A bound on symbolic work, counted while the graph is built. While an ExprBudget is alive it
// is its thread's current budget: every node a builder makes (expr/expr.hpp) is charged to it,
// and the first node over the limit throws Error(TooLarge, "<path>: ...") at once, so refusing
// an expression that would explode costs no more than the limit itself.
#pragma once
#include <cstddef>
#include <string>

namespace pdesurf {

class ExprBudget {
 public:
  // what: the work, for the message ("the derived conditions of the scene's ends").
  ExprBudget(size_t limit, std::string what);
  ~ExprBudget();  // the enclosing budget (if any) becomes current again
  ExprBudget(const ExprBudget&) = delete;
  ExprBudget& operator=(const ExprBudget&) = delete;

  // The place the next nodes are charged to, named in the error (e.g. "patches[2].ends.u1").
  void setPath(std::string path) { path_ = std::move(path); }
  size_t used() const { return used_; }
  size_t limit() const { return limit_; }

  // Charges one node to the current budget; a no-op when there is none.
  static void charge();

 private:
  [[noreturn]] void refuse() const;
  size_t limit_, used_ = 0;
  std::string what_, path_;
  ExprBudget* outer_;
};

}  // namespace pdesurf
