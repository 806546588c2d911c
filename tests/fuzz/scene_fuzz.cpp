// libFuzzer target: scene text -> parseScene -> solveScene -> tessellate every patch (16×16,
// with curvature when the input's length is odd) -> join certificate (no crossing test).
// Expected outcome for bad input: a named pdesurf::Error. A finding is anything else: a
// crash or sanitizer report, an exception of another type, an Error(Internal) (a bug by the
// core's own definition), or a non-finite float in a mesh that tessellate returned.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "analysis/join_certificate.hpp"
#include "common/errors.hpp"
#include "scene/scene.hpp"
#include "surface/mesh.hpp"

namespace {

constexpr int kGrid = 16;

void requireFinite(const std::vector<float>& values, const char* buffer, const pdesurf::Patch& patch) {
  for (size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      std::fprintf(stderr, "scene_fuzz: non-finite %s[%zu] = %g in the mesh of patch '%s'\n", buffer, i,
                   static_cast<double>(values[i]), patch.name.c_str());
      std::abort();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const bool curvature = size % 2 == 1;
  try {
    const pdesurf::Scene scene = pdesurf::parseScene(text);
    const std::vector<pdesurf::SolvedPatch> solved = pdesurf::solveScene(scene);
    for (const pdesurf::SolvedPatch& s : solved) {
      const pdesurf::Mesh mesh = pdesurf::tessellate(s.surface, kGrid, kGrid, curvature);
      requireFinite(mesh.positions, "positions", *s.patch);
      requireFinite(mesh.normals, "normals", *s.patch);
      requireFinite(mesh.meanCurvature, "meanCurvature", *s.patch);
      requireFinite(mesh.gaussCurvature, "gaussCurvature", *s.patch);
    }
    pdesurf::checkScene(scene, solved, 0);
  } catch (const pdesurf::Error& e) {
    if (e.code() == pdesurf::ErrorCode::Internal) {
      std::fprintf(stderr, "scene_fuzz: Error(Internal): %s\n", e.what());
      std::abort();
    }
  }
  return 0;
}
