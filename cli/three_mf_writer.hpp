// pdesurf export -o FILE.3mf: the model's watertight mesh as a 3MF package for printing, written
// by lib3mf (the 3MF Consortium's library; Debian's lib3mf 1.8): one mesh object per body
// (analysis/watertight_mesh.hpp's bodyMeshes, named as the page names them), each a build item,
// in millimetres (3MF's default, what slicers assume), the scene's title as metadata.
#pragma once
#include <string>

#include "analysis/watertight_mesh.hpp"

namespace pdesurf::cli {

// Throws std::runtime_error naming lib3mf's error when a call fails (e.g. the file cannot be written).
void write3mf(const std::string& path, const std::string& title, const ModelMesh& mesh);

}  // namespace pdesurf::cli
