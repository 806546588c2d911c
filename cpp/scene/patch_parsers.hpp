// Each kind's parser of a scene patch (scene/patch_kinds.cpp calls them): the JSON object `j`
// at `path` ("patches[3]") into `patch`; numbers and expressions through `r`. Every error
// names the field.
#pragma once
#include <string>

#include "scene/json_fields.hpp"
#include "scene/scene.hpp"

namespace pdesurf {

// scene/pde_json.cpp
void parsePdePatch(const scene_json::json& j, const std::string& path, const scene_json::Resolver& r, int version, Patch& patch);
// scene/fill_json.cpp (version 4): a pde patch closing a loop of other patches' borders.
void parseFillPatch(const scene_json::json& j, const std::string& path, const scene_json::Resolver& r, int version, Patch& patch);
// scene/bezier_json.cpp (version 2). Adds the patch's assembly work and its normal field's
// sampling to the scene's totals (limits::kBezierAssembly, limits::kFieldSampling). Version 4:
// its "borders" (kept in patch.borders); the control_net may then be left out.
void parseBezierPatch(const scene_json::json& j, const std::string& path, const scene_json::Resolver& r, int version, Patch& patch,
                      scene_json::BezierWork& work);
// scene/primary_json.cpp: the primary surfaces.
void parseRuled(const scene_json::json& j, const std::string& path, const scene_json::Resolver& r, Patch& patch);
void parseSeparable(const scene_json::json& j, const std::string& path, const scene_json::Resolver& r, Patch& patch);
void parseSurface(const scene_json::json& j, const std::string& path, const scene_json::Resolver& r, int version, Patch& patch);

}  // namespace pdesurf
