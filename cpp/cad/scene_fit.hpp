// Every patch of a solved scene as a B-spline surface for CAD, each with its certificate:
// Bézier patches exactly (their net), the others by the certified fit (bspline_fit.hpp).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "cad/bspline_fit.hpp"
#include "scene/scene.hpp"

namespace pdesurf {

struct PatchFit {
  BSplineSurface surface;  // named after the patch
  FitReport report;
};

struct SceneFitOptions {
  double tolerance = 0.0;  // absolute, scene units; 0: the default, 1e-6 of the scene's diagonal
  int degree = 5;
  // Told after each patch: how many are fitted of how many, and the one just done (the page's
  // progress bar; the fit of one patch is the unit of work).
  std::function<void(size_t done, size_t total, const std::string& patch)> progress;
};

constexpr double kDefaultFitTolerance = 1e-6;  // of the scene's bounding-box diagonal

// The bounding-box diagonal of every patch, from a 33×33 grid each.
double sceneDiagonal(const std::vector<SolvedPatch>& solved);

// FitOptions of the scene: the tolerance resolved (0: the default of the diagonal) and checked
// (Error InvalidField when it is not positive and finite).
FitOptions resolveFitOptions(const std::vector<SolvedPatch>& solved, const SceneFitOptions& options);

// One patch's face: a Bézier net as it is, else the certified fit. Errors name the patch. Reads
// only `patch` (and its surface's expressions): patches of different threads' solved scenes can
// be fitted at once.
PatchFit fitPatch(const SolvedPatch& patch, const FitOptions& fit);

// Throws Error naming the patch ("patch 'blend': the fit reached …") when one cannot reach the
// tolerance within the limits; nothing is returned then. *tolerance gets the one used.
std::vector<PatchFit> fitScene(const std::vector<SolvedPatch>& solved, const SceneFitOptions& options,
                               double* tolerance = nullptr);

}  // namespace pdesurf
