// Version 4: the conditions a pde patch takes from other, already solved patches, written into a
// copy of its problem before it is solved (solveScene solves in Scene::solveOrder).
//   A chained end (docs/chains-and-fills.md) continues the edge it names: with d the derivative across
//   that edge pointing out of its patch and p the end's power,
//     X = the edge,  X_u = ±p d  (+ at u0, - at u1),  X_uu = p² d_dd,
//   so consecutive patches meet G1 (4th order) or G2 (6th order), exactly, from the solved
//   surface's own terms (a pde patch's end) or its control net (a Bézier border).
//   A fill (docs/chains-and-fills.md): scene/fill_conditions.cpp.
#pragma once
#include <functional>
#include <memory>

#include "scene/scene.hpp"

namespace pdesurf {

using SolvedLookup = std::function<const SolvedPatch&(const std::string&)>;

// The patch's problem with every chained end and its fill's loop derived; throws
// Error(InvalidField | NonFinite | TooLarge) naming the reference. sceneNodes: the nodes the
// solve's earlier derivations built, grown by this one's (limits::kSceneDerivedNodes bounds the
// sum: what is left of it bounds this derivation while it builds).
std::shared_ptr<const PdeProblem> derivedProblem(const Patch& patch, const SolvedLookup& solved, size_t* sceneNodes = nullptr);

// In scene/fill_conditions.cpp: the fill's conditions at u = 0 (the loop) and u = 1 (its centre).
void deriveFill(const Patch& fill, const SolvedLookup& solved, PdeProblem& out);

}  // namespace pdesurf
