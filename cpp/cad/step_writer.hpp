// ISO 10303-21 (STEP AP214) text for a set of B-spline faces with their topology
// (cad/brep_topology.hpp): one product; each connected set of faces one shell. When every
// shell is closed, each bounds a MANIFOLD_SOLID_BREP of an ADVANCED_BREP_SHAPE_REPRESENTATION;
// else a MANIFOLD_SURFACE_SHAPE_REPRESENTATION holds one SHELL_BASED_SURFACE_MODEL of the
// shells (OPEN_SHELL, CLOSED_SHELL). Each ADVANCED_FACE is named after its surface; a shared
// edge is one EDGE_CURVE both faces name. Lengths in millimetres; the tolerance is the
// context's UNCERTAINTY_MEASURE_WITH_UNIT. docs/cad-formats.md says how readers get the names back.
#pragma once
#include <string>
#include <vector>

#include "cad/bspline_surface.hpp"
#include "cad/cad_file.hpp"

namespace pdesurf {

struct BrepTopology;

// Throws Error(InvalidField) (checkFacesForCad) when a face cannot be written. Without a
// topology, the faces share nothing: one open shell each.
std::string writeStep(const std::vector<BSplineSurface>& faces, const CadFileInfo& info, const BrepTopology* topology = nullptr);

// A STEP string literal for UTF-8 text: quoted, an apostrophe doubled, a backslash doubled,
// non-ASCII as \X2\…\X0\ directives (\X4\ beyond the BMP), control characters as spaces.
std::string stepString(const std::string& utf8);

}  // namespace pdesurf
