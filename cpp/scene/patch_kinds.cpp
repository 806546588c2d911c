#include "scene/patch_kinds.hpp"

#include "bezier/bezier_solver.hpp"
#include "scene/patch_parsers.hpp"

namespace pdesurf {

namespace {

void parseBezier(const PatchParse& in, Patch& patch) {
  try {
    parseBezierPatch(in.j, in.path, in.r, in.version, patch, in.bezierWork);
    // A net left out (four borders by reference) is checked once deriveBorders has built it.
    if (!patch.bezier().initial.empty()) validateBezierProblem(patch.bezier());
  } catch (const Error& e) {
    const std::string what = e.what();
    throw Error(e.code(), what.rfind(in.path, 0) == 0 ? what : in.path + ": " + what);
  }
}

}  // namespace

const std::vector<PatchKindEntry>& patchKinds() {
  static const std::vector<PatchKindEntry> kinds = {
      {"pde", PatchKind::Pde, 1, [](const PatchParse& in, Patch& p) { parsePdePatch(in.j, in.path, in.r, in.version, p); },
       "its ends' conditions from the surfaces they meet (version 3) or the patches they continue (version 4)",
       "u0 and u1 (its ends, by chains and fills); v0 = v1 when it closes (a seam)"},
      {"fill", PatchKind::Fill, 4, [](const PatchParse& in, Patch& p) { parseFillPatch(in.j, in.path, in.r, in.version, p); },
       "its loop's position and tangents from the borders it names, its centre from the loop",
       "u0 (the loop, in parts, one per border); u1 collapses to the centre"},
      {"surface", PatchKind::Primary, 2, [](const PatchParse& in, Patch& p) { parseSurface(in.j, in.path, in.r, in.version, p); },
       "nothing (a blend may trim it along a curve)", "t0 and t1 (its borders), or the curve a blend trims it along"},
      {"bezier", PatchKind::Bezier, 2, parseBezier, "its borders' two outer rings from the surfaces they lie on (version 4)",
       "u0, u1, v0 and v1"},
      {"ruled", PatchKind::Primary, 1, [](const PatchParse& in, Patch& p) { parseRuled(in.j, in.path, in.r, p); }, "nothing",
       "t0 and t1 (its borders)"},
      {"separable", PatchKind::Primary, 1, [](const PatchParse& in, Patch& p) { parseSeparable(in.j, in.path, in.r, p); }, "nothing",
       "t0 and t1 (its borders)"},
  };
  return kinds;
}

const PatchKindEntry* findPatchKind(const std::string& name, int version) {
  for (const PatchKindEntry& k : patchKinds())
    if (name == k.name && version >= k.since) return &k;
  return nullptr;
}

std::string patchKindNames(int version) {
  std::string out;
  for (const PatchKindEntry& k : patchKinds())
    if (version >= k.since) out += (out.empty() ? "" : ", ") + std::string(k.name);
  return out;
}

}  // namespace pdesurf
