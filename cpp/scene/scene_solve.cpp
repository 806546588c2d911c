#include <string>

#include "common/errors.hpp"
#include "pde/closed_form.hpp"
#include "scene/scene.hpp"

namespace pdesurf {

const char* patchKindName(PatchKind kind) { return kind == PatchKind::Pde ? "pde" : "ruled"; }

const Patch* Scene::find(const std::string& name) const {
  for (const Patch& p : patches)
    if (p.name == name) return &p;
  return nullptr;
}

const Patch* Scene::firstPde() const {
  for (const Patch& p : patches)
    if (p.kind == PatchKind::Pde) return &p;
  return nullptr;
}

namespace {

// A ruled surface is separable too: C-terms carry the u-factor 1, D-terms the u-factor t.
SeparableSurface ruledToSeparable(const RuledSurface& r) {
  SeparableSurface s;
  s.u0 = r.t0;
  s.u1 = r.t1;
  s.v0 = r.v0;
  s.v1 = r.v1;
  for (int c = 0; c < 3; ++c) {
    for (const VTerm& t : r.curve[c]) s.component[c].push_back({t.g, UFactor::polynomial({t.coef})});
    for (const VTerm& t : r.direction[c]) s.component[c].push_back({t.g, UFactor::polynomial({0.0, t.coef})});
  }
  return s;
}

}  // namespace

SeparableSurface solvePatch(const Patch& patch) {
  try {
    if (patch.kind == PatchKind::Ruled) return ruledToSeparable(patch.ruled);
    return solveClosedForm(patch.pde);
  } catch (const Error& e) {
    throw Error(e.code(), "patch '" + patch.name + "': " + e.what());
  }
}

std::vector<SolvedPatch> solveScene(const Scene& scene) {
  std::vector<SolvedPatch> out;
  for (const Patch& p : scene.patches) out.push_back({&p, solvePatch(p)});
  return out;
}

}  // namespace pdesurf
