// IGES 5.3 text for a set of B-spline faces: each face one rational B-spline
// surface entity (type 128, polynomial flag set, closed-in-v flag from the seam) bounded by
// its parameter ranges, named by its entity label (first 8 characters) and a name property
// (type 406 form 15, the whole name). Units millimetres; the tolerance is the global section's
// minimum resolution. IGES text is ASCII: other characters become '?'.
#pragma once
#include <string>
#include <vector>

#include "cad/bspline_surface.hpp"
#include "cad/cad_file.hpp"

namespace pdesurf {

struct BrepTopology;

// Throws Error(InvalidField) (checkFacesForCad) when a face cannot be written. With a topology
// (cad/brep_topology.hpp, built on these faces): a B-rep, a manifold solid (186) per closed
// shell and an open shell (514 form 2) per other body, the faces (510) named instead of the
// surfaces; without: the surfaces alone, each a root.
std::string writeIges(const std::vector<BSplineSurface>& faces, const CadFileInfo& info, const BrepTopology* topology = nullptr);

// UTF-8 text as IGES string content: printable ASCII kept, controls as spaces, others '?'.
std::string igesText(const std::string& utf8);

}  // namespace pdesurf
