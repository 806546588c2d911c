// Scene version 2: boundary functions, forces and primary surfaces written as expressions,
// split into closed-form terms and general remainders (expr/split.hpp).
#pragma once
#include <string>

#include "pde/pde_problem.hpp"
#include "scene/json_fields.hpp"
#include "scene/scene.hpp"

namespace pdesurf::scene_json {

// An expression in v: family terms, plus one general term for what does not split (its text
// is the user's, for error messages). c·general(f) with f one family function keeps f as its
// origin, so the closed form stays available to measure the general methods against.
// `parsed`, when given, receives the expression before it is split.
VExpansion slotExpression(const json& j, const std::string& path, const Resolver& r, Expr* parsed = nullptr);

// The same for an expression built in code (a derived end); `text` names it in errors.
VExpansion slotFromExpr(const Expr& e, const std::string& text);

// An expression in u and v: (polynomial in u) × family terms, and a general force.
void forceExpression(const json& j, const std::string& path, const Resolver& r, ComponentProblem& cp);

// An expression in t and v for one coordinate of a primary surface, parsed; and split into
// separable terms plus what does not separate.
Expr surfaceField(const json& j, const std::string& path, const Resolver& r);
void splitSurface(const Expr& e, std::vector<PrimaryTerm>& terms, Expr* pointwise);

}  // namespace pdesurf::scene_json
