// The join certificate (docs/analysis.md): along every declared join (a primary surface's
// `meets`: a PDE patch end or a Bézier border) the position gap, the tangent-plane angle, the
// normal-curvature mismatch across the join and a fold test, from analytic derivatives at
// kJoinSamples points; a verdict against what the patch promises (2nd order G0, 4th G1, 6th
// G2; a membrane Bézier G0, a thin plate G1); plus the crossings found (analysis/crossings).
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "analysis/crossings.hpp"
#include "analysis/edge_samples.hpp"
#include "analysis/fill_centre.hpp"
#include "scene/scene.hpp"

namespace pdesurf {

constexpr int kJoinSamples = 256;
constexpr double kG0Tolerance = 1e-9;   // of the join's size (JoinResult::size)
constexpr double kG1ToleranceDeg = 1e-6;
constexpr double kG2Tolerance = 1e-6;   // relative

struct JoinResult {
  std::string patch;    // the PDE or Bézier patch
  std::string end;      // "u0", "u1", "v0", "v1"
  std::string surface;  // the primary surface
  std::string edge;     // "t0", "t1", or "curve replacing t0" / "curve replacing t1" (a trimline)
  int level = 0;        // promised: 0 G0, 1 G1, 2 G2
  double size = 0.0;    // what is joined: the diagonal of the promising patch's box and the met edge's
  double g0 = 0.0;      // largest gap / size
  double g1Deg = 0.0;   // largest tangent-plane angle, degrees (level >= 1 and measured)
  double g2Rel = 0.0;   // largest relative normal-curvature mismatch across (level 2 only)
  double worstV = 0.0;  // the primary's v where the promised figure is worst
  bool fold = false;    // both surfaces leave the edge on the same side somewhere
  int degenerate = 0;   // points where the promised figure cannot be measured (zero speed, pole)
  bool ok = false;
};

struct SceneReport {
  double sceneSize = 0.0;  // bounding-box diagonal of every patch (32×32 samples)
  std::vector<JoinResult> joins;
  std::vector<JoinResult> seams;  // closed patches joined to themselves (certifySeams)
  std::vector<Crossing> crossings;
  std::vector<FillCentre> centres;  // every fill's centre (version 4)
  bool ok = true;  // every join keeps its promise, every centre is regular and nothing crosses
};

const char* levelName(int level);  // "G0", "G1", "G2"

// Where the certificate reads an edge: `patch`'s edge u = end (alongU false) or v = end
// (alongU true) at the parameters `at` along it. By default the solved surfaces; a CAD export
// measures its fitted faces through the same door (cad/fitted_joins.hpp).
using EdgeReader = std::function<std::vector<EdgePoint>(const SolvedPatch& patch, bool alongU, int end, const std::vector<double>& at)>;

// The parameter ranges of one join (a Meets on `primary`): the target's border a0..a1 (a
// fill's side: its part, part = true) and the met edge's p0..p1 (given, else the same v as a
// PDE target, else the primary's v-range), before Meets::reversed. The certificate reads them,
// and the CAD topology (cad/border_joins.cpp).
struct JoinRanges {
  bool part = false;
  double a0 = 0, a1 = 0, p0 = 0, p1 = 0;
};
JoinRanges joinRanges(const Meets& m, const SeparableSurface& primary, const SolvedPatch& target);

// Every join's tolerances are relative to what it joins (JoinResult::size: the promising
// patch's bounding box with the met edge's samples), never to the rest of the scene: a far
// patch elsewhere cannot hide a gap. The verdicts (ok) are the solved surfaces' tolerances;
// another reader's caller judges its own.
std::vector<JoinResult> certifyJoins(const Scene& scene, const std::vector<SolvedPatch>& solved, const EdgeReader& read = nullptr);
// One of them: patch solved[i]'s declared join meets[k] (errors named as certifyJoins names them).
JoinResult certifyJoin(const Scene& scene, const std::vector<SolvedPatch>& solved, size_t i, size_t k, const EdgeReader& read = nullptr);
// Every pde patch whose v closes on itself (both u-edges are loops) joined to itself along
// v = v0 and v = v1: patch = surface = its name, end "v1", edge "v0", worstV the u where the
// figure is worst. At least G1, G2 where the patch promises curvature. Its size: the patch's.
std::vector<JoinResult> certifySeams(const std::vector<SolvedPatch>& solved);
// One of them: nothing when the patch is not a pde patch closed in v.
std::optional<JoinResult> certifySeam(const SolvedPatch& patch);
// The diagonal of all patches' bounding boxes (32×32 samples each): the crossings' and the
// bodies' scale. patchSizeOf: one patch's.
double sceneSizeOf(const std::vector<SolvedPatch>& solved);
double patchSizeOf(const SeparableSurface& surface);
// Joins, seams, fills' centres, then crossings on a crossingGrid × crossingGrid mesh of every patch (0: none).
SceneReport checkScene(const Scene& scene, const std::vector<SolvedPatch>& solved, int crossingGrid = 64);

}  // namespace pdesurf
