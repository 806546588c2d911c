#include "scene/chain_conditions.hpp"

#include <algorithm>

#include "common/limits.hpp"
#include "expr/budget.hpp"
#include "scene/expression_fields.hpp"
#include "scene/patch_graph.hpp"
#include "scene/solved_edges.hpp"

namespace pdesurf {

namespace {

Vec3Expr onParameter(const Vec3Expr& e, const Expr& s) {
  return {substitute(e[0], ExprVar::V, s), substitute(e[1], ExprVar::V, s), substitute(e[2], ExprVar::V, s)};
}

void deriveChainEnd(const Patch& patch, int end, const SolvedLookup& solved, PdeProblem& out) {
  const EndReference& ref = patch.ends()[end];
  const SolvedPatch& source = solved(ref.patch);
  int slots = 0;
  for (const ComponentOperator& op : patch.op()) slots = std::max(slots, op.order / 2);
  EdgeExprs e = solvedEdge(source, ref.patchEdge, slots - 1);
  if (source.patch->kind == PatchKind::Bezier) {
    // The border's parameter [0, 1] runs over this patch's v-range (backwards with reverse).
    const double v0 = out.v0, v1 = out.v1;
    Expr s = divide(subtract(variable(ExprVar::V), constant(v0)), constant(v1 - v0));
    if (ref.reverse) s = subtract(constant(1.0), s);
    e.X = onParameter(e.X, s), e.out = onParameter(e.out, s), e.outOut = onParameter(e.outOut, s);
  }
  const double p = ref.power->value, sign = end == 0 ? 1.0 : -1.0;
  const std::string from = "'" + source.patch->name + "' " + edgeName(*source.patch, ref.patchEdge);
  for (int c = 0; c < 3; ++c) {
    ComponentProblem& cp = out.component[c];
    std::vector<VExpansion>& slot = end == 0 ? cp.left : cp.right;
    const int n = patch.op()[c].order / 2;
    slot.assign(n, {});
    const Expr conditions[3] = {e.X[c], multiply(constant(sign * p), e.out[c]), multiply(constant(p * p), e.outOut[c])};
    for (int i = 0; i < n; ++i) slot[i] = scene_json::slotFromExpr(conditions[i], ref.path + " (from " + from + ")");
  }
}

}  // namespace

std::shared_ptr<const PdeProblem> derivedProblem(const Patch& patch, const SolvedLookup& solved, size_t* sceneNodes) {
  auto out = std::make_shared<PdeProblem>(patch.pde());
  const size_t used = sceneNodes ? std::min(*sceneNodes, limits::kSceneDerivedNodes) : 0;
  const bool sceneBound = limits::kSceneDerivedNodes - used < limits::kDerivedNodes;
  ExprBudget budget(sceneBound ? limits::kSceneDerivedNodes - used : limits::kDerivedNodes,
                    sceneBound ? "the conditions derived from solved patches, summed over the scene (" + std::to_string(used) + " nodes before this patch's),"
                               : std::string("the conditions derived from solved patches"));
  for (int end = 0; end < 2; ++end) {
    if (!patch.ends()[end].given || patch.ends()[end].patch.empty()) continue;
    budget.setPath(patch.ends()[end].path);
    deriveChainEnd(patch, end, solved, *out);
  }
  if (patch.isFill()) {
    budget.setPath(patch.fill().path);
    deriveFill(patch, solved, *out);
  }
  if (sceneNodes) *sceneNodes += budget.used();
  return out;
}

}  // namespace pdesurf
