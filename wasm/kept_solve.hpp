// The module's last solve (solveScene, solveSceneWith), kept for what the page asks of it
// afterwards: its join report part by part (report_bindings.cpp). One module serves one page
// (its worker), so "the last solve" is that page's; a new solve replaces it.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "scene/scene.hpp"

namespace pdesurf::wasm {

struct KeptSolve {
  std::shared_ptr<const Scene> scene;                      // the patches `solved` points into
  std::shared_ptr<const std::vector<SolvedPatch>> solved;
  uint64_t generation = 0;  // bumped by every solve
};

void keepSolve(std::shared_ptr<const Scene> scene, std::shared_ptr<const std::vector<SolvedPatch>> solved);

}  // namespace pdesurf::wasm
