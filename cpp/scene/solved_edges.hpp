// An edge of a solved patch as expressions in its own parameter (ExprVar::V): the position,
// the derivative across it pointing out of the patch, and the second derivative across. What
// a chained end or a fill's border is derived from (scene/chain_conditions.hpp): exact, the
// solved surface's own terms (a Bézier border from its control net, as a polynomial).
#pragma once
#include <array>

#include "scene/scene.hpp"

namespace pdesurf {

using Vec3Expr = std::array<Expr, 3>;

struct EdgeExprs {
  Vec3Expr X, out, outOut;  // outOut only when asked for (derivatives = 2)
  double a0 = 0.0, a1 = 1.0;  // the edge parameter's range
};

// edge: a surface's or pde patch's 0 (t0/u0) or 1 (t1/u1); a Bézier patch's kBezierEdge.
EdgeExprs solvedEdge(const SolvedPatch& sp, int edge, int derivatives);

// g(v) of a basis function as an expression (general ones: their own expression).
Expr functionExpr(const VFunction& g);

}  // namespace pdesurf
