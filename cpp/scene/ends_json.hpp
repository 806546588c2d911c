// Version 3: the "ends" field of a pde patch (ends by reference, docs/blends-by-reference.md).
#pragma once
#include <string>

#include "scene/json_fields.hpp"
#include "scene/scene.hpp"

namespace pdesurf::scene_json {

// Reads patch.ends from `j` ({"u0": {...}, "u1": {...}}); returns the operator order the
// highest continuity asks (position 2, tangency 4, curvature 6).
int parseEnds(const json& j, const std::string& path, const Resolver& r, Patch& patch);

}  // namespace pdesurf::scene_json
