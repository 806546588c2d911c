// ISO 10303-21 (STEP AP214) text for a set of B-spline faces: one product whose
// MANIFOLD_SURFACE_SHAPE_REPRESENTATION holds one SHELL_BASED_SURFACE_MODEL of OPEN_SHELLs,
// one a face (faces share no topology, and an open shell is a connected set), each
// ADVANCED_FACE named after its surface and bounded by its own edges. Lengths in millimetres; the tolerance is the
// context's UNCERTAINTY_MEASURE_WITH_UNIT. docs/cad-formats.md says how readers get the names back.
#pragma once
#include <string>
#include <vector>

#include "cad/bspline_surface.hpp"
#include "cad/cad_file.hpp"

namespace pdesurf {

// Throws Error(InvalidField) (checkFacesForCad) when a face cannot be written.
std::string writeStep(const std::vector<BSplineSurface>& faces, const CadFileInfo& info);

// A STEP string literal for UTF-8 text: quoted, an apostrophe doubled, a backslash doubled,
// non-ASCII as \X2\…\X0\ directives (\X4\ beyond the BMP), control characters as spaces.
std::string stepString(const std::string& utf8);

}  // namespace pdesurf
