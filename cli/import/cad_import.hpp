// `pdesurf import`: a STEP or IGES file's faces as a scene, one "surface" patch per face given
// as NURBS (scene/nurbs_json.hpp), read with Open CASCADE. Analytic faces (planes, cylinders,
// cones, spheres, tori) are written as their expressions in OCCT's own parametrisation (exact,
// and closed-form families for blends); other surfaces (Bézier, revolved, extruded, offset)
// are converted to B-splines by OCCT's GeomConvert over the face's bounds. A face's (u, v) is
// the patch's (t, v) (for converted surfaces, OCCT's conversion's), its parameter bounds the
// patch's ranges — swapped for a face closed in u only (a cylinder's angle): pdesurf's v runs
// around, and blends meet the t-borders (the rims). Trims are not kept: a face is drawn over the box of
// its parameter bounds (said in the scene's description). Built only where OCCT is installed.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace pdesurf::cad_import {

// The largest file read (docs/limits.md): a larger one is refused before it is opened.
constexpr long long kMaxFileBytes = 64ll << 20;

// Throws pdesurf::Error naming the file or the face ("face 'lid' (3 of 12): …"); nothing is
// returned half-made. The scene it returns parses (it is checked by parseScene before return).
nlohmann::json importCadFile(const std::string& path);

}  // namespace pdesurf::cad_import
