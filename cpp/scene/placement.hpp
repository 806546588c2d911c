// Scene version 4: a "surface" patch's placement, {"translate": [x, y, z], "rotate": [rx, ry, rz]
// (degrees), "scale": s | [sx, sy, sz]}, applied to its expressions symbolically:
// X' = T + R·diag(s)·X with R = Rx·Ry·Rz (three.js Euler order 'XYZ'). A blend by reference
// derives its ends from the placed expressions, so it follows a moved surface exactly.
#pragma once
#include <array>
#include <string>

#include <Eigen/Dense>

#include "expr/expr.hpp"
#include "scene/json_fields.hpp"

namespace pdesurf::scene_json {

struct Placement {
  Eigen::Matrix3d linear = Eigen::Matrix3d::Identity();  // R·diag(s)
  Eigen::Vector3d translate = Eigen::Vector3d::Zero();
};

// Reads the field (numbers or expressions over the parameters); a non-finite value, a zero
// scale or a malformed vector is a named error at `path`.
Placement parsePlacement(const json& j, const std::string& path, const Resolver& r);

// The three coordinates' expressions placed: each a linear combination of the originals.
std::array<Expr, 3> applyPlacement(const Placement& p, const std::array<Expr, 3>& xyz);

// How far a patch may be moved, in its own sizes: beyond it, double precision rounds its
// placed points by more than the join certificate's G0 tolerance (1e-9 of a join's size), and a
// blend derived from it silently loses its shape (issue 38: a plane at x = 1e16 put the
// sphere fillet's ring 1.4 off, certified).
constexpr double kPlacementReach = 1e6;
// The smallest scale's magnitude (and 1 / it the largest) a placement may apply.
constexpr double kPlacementScaleMin = 1e-12;
// Refuses (InvalidField at `path`.translate) a translation beyond kPlacementReach times the
// placed surface's size, sampled at 9 × 9 points of t in [t0, t1], v in [v0, v1].
void checkPlacementReach(const Placement& p, const std::array<Expr, 3>& xyz, double t0, double t1, double v0, double v1,
                         const std::string& path);

}  // namespace pdesurf::scene_json
