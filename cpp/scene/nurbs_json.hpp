// A "surface" patch given as a NURBS surface (its "nurbs" field, instead of the expressions
// x, y, z): degrees, full knot vectors, control points (rows along t) and optional weights.
// Each coordinate becomes an expression of B-spline functions (expr/spline.hpp),
//   X(t, v) = Σ_i N_i(t) A_i(v) / Σ_i N_i(t) W_i(v),  A_i(v) = Σ_j w_ij P_ij M_j(v),
// summed over the direction with fewer rows, so the rest of the core — drawing, analysis,
// blends and fills by reference, trimlines, the CAD fit — takes it as any typed surface.
#pragma once
#include <array>
#include <string>

#include "expr/expr.hpp"
#include "scene/json_fields.hpp"

namespace pdesurf {

struct NurbsDomain {
  double t0, t1, v0, v1;
};

// Throws Error naming the field (…".nurbs.knots[1][4]") for anything that is not a valid
// NURBS surface or that exceeds limits::kNurbsDegree / kNurbsPoints.
std::array<Expr, 3> parseNurbs(const scene_json::json& j, const std::string& path, NurbsDomain* domain);

}  // namespace pdesurf
