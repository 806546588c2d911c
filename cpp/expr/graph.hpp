// Walks over the expression DAG without recursion (internal to expr/).
#pragma once
#include <vector>

#include "expr/expr.hpp"

namespace pdesurf {

// The distinct nodes reachable from the roots, children before parents, each once, as
// pointers to the Expr that holds them (a root, or a parent's operand). With onlyVar >= 0,
// nodes that do not depend on that variable are left out (with everything below them).
std::vector<const Expr*> topologicalOrder(const std::vector<const Expr*>& roots, int onlyVar = -1);

}  // namespace pdesurf
