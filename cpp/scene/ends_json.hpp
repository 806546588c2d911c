// Version 3: the "ends" field of a pde patch (ends by reference, docs/blends-by-reference.md).
#pragma once
#include <string>

#include "scene/json_fields.hpp"
#include "scene/scene.hpp"

namespace pdesurf::scene_json {

// Reads patch.ends from `j` ({"u0": {...}, "u1": {...}}); returns the operator order the
// highest continuity asks (position 2, tangency 4, curvature 6).
// Version 4 also takes an end on another patch: {"patch", "at": "u0"...}, a chain.
int parseEnds(const json& j, const std::string& path, const Resolver& r, int version, Patch& patch);

// "position", "tangency", "curvature".
Continuity continuityOf(const json& j, const std::string& path);
// "u0", "u1", "v0", "v1" (kBezierEdge's order), with surfaceNames also "t0", "t1" (as u0, u1).
int edgeIndex(const std::string& at, const std::string& path, bool surfaceNames);
// A trimline curve `at` = {"t": "<expression in v>", "replaces": "t0" | "t1"} (default t0):
// sets e.curve, e.tau and e.atT1 (the border it replaces). path names `at`.
void parseTrimCurve(const json& at, const std::string& path, const Resolver& r, EndReference& e);

}  // namespace pdesurf::scene_json
