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

}  // namespace pdesurf::scene_json
