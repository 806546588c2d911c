// The "surface" patch that a reference names (a blend's end, a fill's border).
#pragma once
#include <cstddef>
#include <string>

#include "scene/scene.hpp"

namespace pdesurf::scene_json {

// Its index in scene.patches. A name no patch has, or a patch that is not a "surface"
// (expressions in t and v), is a named error at `path`.surface; `referrer` says who refers
// ("an end", "a border").
size_t referencedSurface(const Scene& scene, const std::string& name, const std::string& path, const char* referrer);

}  // namespace pdesurf::scene_json
