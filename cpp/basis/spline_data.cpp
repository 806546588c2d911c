#include "basis/spline_data.hpp"

#include <unordered_set>
#include <vector>

#include "basis/general_function.hpp"

namespace pdesurf {

bool hasSplineData(const VExpansion& f) {
  std::unordered_set<const ExprNode*> seen;
  for (const VTerm& term : f) {
    if (!term.g.isGeneral()) continue;
    std::vector<const ExprNode*> stack{term.g.general->expr().get()};
    while (!stack.empty()) {
      const ExprNode* e = stack.back();
      stack.pop_back();
      if (!e || !seen.insert(e).second) continue;
      if (e->op == ExprNode::Op::Spline) return true;
      stack.push_back(e->a.get());
      stack.push_back(e->b.get());
    }
  }
  return false;
}

}  // namespace pdesurf
