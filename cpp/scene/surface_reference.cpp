#include "scene/surface_reference.hpp"

#include "common/errors.hpp"
#include "scene/json_fields.hpp"

namespace pdesurf::scene_json {

size_t referencedSurface(const Scene& scene, const std::string& name, const std::string& path, const char* referrer) {
  size_t index = scene.patches.size();
  for (size_t i = 0; i < scene.patches.size(); ++i)
    if (scene.patches[i].name == name) index = i;
  if (index == scene.patches.size()) fail(ErrorCode::UnknownName, path + ".surface", "no patch named '" + name + "'");
  const Patch& s = scene.patches[index];
  if (s.kind != PatchKind::Primary || !s.primary().full[0] || !s.primary().full[1] || !s.primary().full[2])
    fail(ErrorCode::InvalidField, path + ".surface",
         "'" + name + "' is a " + s.kindName + " patch; " + referrer + " refers to a \"surface\" patch (expressions in t and v)");
  return index;
}

}  // namespace pdesurf::scene_json
