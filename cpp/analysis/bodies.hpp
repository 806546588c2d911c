// The model's bodies (issue 36): its patches joined into shells by the joins the certificate
// records (cad/brep_topology.hpp, built on the solved surfaces themselves), each with its area
// and, when closed, the volume it encloses, integrated over the exact surfaces, not a mesh.
#pragma once
#include <string>
#include <vector>

#include "cad/border_joins.hpp"
#include "cad/brep_topology.hpp"
#include "cad/topology_face.hpp"
#include "scene/scene.hpp"

namespace pdesurf {

struct Body {
  std::vector<std::string> patches;
  bool closed = false;  // every border shared with another patch (or a seam, or collapsed)
  double area = 0;      // scene units²
  double volume = 0;    // closed only, scene units³
  int freeEdges = 0;    // pieces of border met by no other patch
};

// sceneSize: the scene's diagonal (join_certificate's sceneSizeOf): borders are one edge where
// they are within 1e-8 of it. Area and volume: Gauss-Legendre, 4 points a cell, cells cut at the
// surfaces' creases (a fill's corners) and graded towards u = 0 (a lift's decay).
// measures: each patch's faceMeasure when known (a report session keeps them per surface).
// With them, what the topology asks of a face's borders, kept as distances so that a report
// session can keep them while the scene's size (the tolerance) changes.
struct FaceMeasure {
  double area = 0, signedVolume = 0;  // ∫ |X_u × X_v|, (1/3) ∫ X · (X_u × X_v)
  double seamGap = 0;                 // the largest |X(u, v0) - X(u, v1)| at u0, the middle and u1
  double borderSpread[4] = {0, 0, 0, 0};  // u0, u1, v0, v1: the farthest of 9 points from the first
};
FaceMeasure faceMeasure(const SeparableSurface& s);
std::vector<Body> measureBodies(const std::vector<SolvedPatch>& solved, double sceneSize,
                                const std::vector<FaceMeasure>* measures = nullptr);

// What measureBodies builds on, for others that follow the bodies (analysis/watertight_mesh):
// the solved patches as faces (their eval refers to `solved`, which must outlive them), the
// joins, and the topology at the bodies' tolerance.
struct SolvedTopology {
  std::vector<TopologyFace> faces;
  std::vector<BorderJoin> joins;
  BrepTopology topology;
};
SolvedTopology solvedTopology(const std::vector<SolvedPatch>& solved, double sceneSize,
                              const std::vector<FaceMeasure>* measures = nullptr);

}  // namespace pdesurf
