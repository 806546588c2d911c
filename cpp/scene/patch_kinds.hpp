// The kinds of scene patch, in one table (issue 39): the name a scene writes, how the core
// solves it, the first scene version that has it, its parser, what it derives from other
// patches and which of its edges others meet. Adding a kind: an entry here, its parser
// (scene/patch_parsers.hpp), its solver and its tests; the page's table is
// web/state/patch-kinds.js (a test checks the two agree). docs/architecture.md has the list.
#pragma once
#include <string>
#include <vector>

#include "scene/json_fields.hpp"
#include "scene/scene.hpp"

namespace pdesurf {

// What a kind's parser is given.
struct PatchParse {
  const scene_json::json& j;
  const std::string& path;
  const scene_json::Resolver& r;
  int version;
  scene_json::BezierWork& bezierWork;  // the scene's Bézier patches' work so far
};

struct PatchKindEntry {
  const char* name;  // as the scene writes it
  PatchKind solvedAs;
  int since;  // the first scene version that has it
  void (*parse)(const PatchParse& in, Patch& patch);
  const char* derives;  // what it takes from other patches, derived when the scene is read or solved
  const char* edges;    // where others meet it (as `meets`, ends and borders name them)
};

// Every kind, in the order error messages list them.
const std::vector<PatchKindEntry>& patchKinds();
// The kind `name` as a scene of `version` may use it, or null.
const PatchKindEntry* findPatchKind(const std::string& name, int version);
// "pde, fill, surface, bezier, ruled, separable": the kinds a scene of `version` may use.
std::string patchKindNames(int version);

}  // namespace pdesurf
