// A model's bodies as openNURBS Breps (issue 36): for each shell of the topology
// (cad/brep_topology.hpp) the bytes of one ON_Brep as openNURBS's ON_BinaryArchive::WriteObject
// writes it (opennurbs_brep_io.cpp), for rhino3dm's CommonObject.decode to add to a .3dm file
// (web/cad/write-3dm.js): rhino3dm's JavaScript API can write B-spline surfaces but not join
// them. Faces share the topology's edges and vertices; a collapsed border is a singular trim,
// a closed face's seam one edge used by two seam trims.
#pragma once
#include <string>
#include <vector>

#include "cad/brep_topology.hpp"
#include "cad/bspline_surface.hpp"

namespace pdesurf {

// The archive versions the bytes are written for: what rhino3dm 8's own encode() gives
// (3dm version 60; an openNURBS version of 2024, as unsigned). decode() must be told them.
constexpr int kOn3dmVersion = 60;
constexpr unsigned kOnOpenNurbsVersion = 2425133316u;

struct OnBrepBody {
  std::vector<int> faces;  // the topology's faces in it
  bool closed = false;
  std::string bytes;       // one ON_Brep object
};

// One per shell of `t`, faces[i] being the topology's face i.
std::vector<OnBrepBody> onBreps(const std::vector<BSplineSurface>& faces, const BrepTopology& t);

}  // namespace pdesurf
