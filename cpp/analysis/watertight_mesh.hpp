// A conforming tessellation of the whole model (issue 36): the patches' meshes share their
// vertices along every join the bodies record (analysis/bodies.hpp), so a closed body's mesh
// uses every edge exactly twice, in opposite directions, with its normals outward.
//
// Each patch keeps its nu×nv grid inside; its border row is replaced by the points of its
// topology edges (one set of points per edge, used by both faces), and the ring between the
// grid and those points is zipped in parameter space. Seams wrap; a collapsed border (a pole,
// a fill's centre) is one vertex.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace pdesurf {

struct ModelMesh {
  std::vector<float> positions;  // 3 per vertex, shared by the parts
  std::vector<float> normals;    // 3 per vertex, unit, outward on a closed body
  std::vector<float> uvs;        // 2 per vertex, or none (a shared vertex has no one (u, v))
  struct Part {
    std::string name;               // the patch
    int body = 0;                   // its body (measureBodies' order)
    std::vector<uint32_t> indices;  // 3 per triangle
  };
  std::vector<Part> parts;  // one per solved patch, in the solved order
  size_t vertexCount() const { return positions.size() / 3; }
};

// One body's own vertices (renumbered in the order of first use) and all its triangles, for
// formats with an object per body (3MF); named after its patch when it has one, else "body N"
// (N from 1, in body order), as the page names them.
struct BodyMesh {
  std::string name;
  std::vector<float> positions;
  std::vector<uint32_t> indices;
};
std::vector<BodyMesh> bodyMeshes(const ModelMesh& mesh);

// nu, nv: the grid cells per patch (at least 3 each: the grid's inner ring needs a row inside).
// sceneSize as for measureBodies.
ModelMesh watertightMesh(const std::vector<SolvedPatch>& solved, double sceneSize, int nu, int nv);

}  // namespace pdesurf
