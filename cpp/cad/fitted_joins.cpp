#include "cad/fitted_joins.hpp"

#include <algorithm>

#include "common/errors.hpp"

namespace pdesurf {
namespace {

// An edge of a fitted face, as analysis/edge_samples.cpp reads one of a solved surface: its
// knots are in the patch's own (u, v), so the parameters are the same.
std::vector<EdgePoint> fittedEdge(const BSplineSurface& b, const SeparableSurface& s, bool alongU, int end,
                                  const std::vector<double>& at) {
  std::vector<EdgePoint> out;
  out.reserve(at.size());
  for (double a : at) {
    const double u = alongU ? a : (end ? s.u1 : s.u0);
    double v = alongU ? (end ? s.v1 : s.v0) : a;
    // A fill's border 0 runs over [-π/n, π/n] of its closed v (fillSideRange): the face holds
    // the part below v0 one period on.
    const double period = s.v1 - s.v0;
    if (v < s.v0) v += period;
    if (v > s.v1) v -= period;
    const Eigen::Vector3d X = evaluate(b, u, v), Xu = evaluate(b, u, v, 1, 0), Xv = evaluate(b, u, v, 0, 1);
    const Eigen::Vector3d Xuu = evaluate(b, u, v, 2, 0), Xuv = evaluate(b, u, v, 1, 1), Xvv = evaluate(b, u, v, 0, 2);
    out.push_back(edgePointFrom(alongU, end, X, Xu, Xv, Xuu, Xuv, Xvv));
  }
  return out;
}

}  // namespace

std::vector<FittedJoin> certifyFittedJoins(const Scene& scene, const std::vector<SolvedPatch>& solved,
                                           const std::vector<PatchFit>& fits, double normalToleranceDeg) {
  if (fits.size() != solved.size()) throw Error(ErrorCode::InvalidField, "one fitted face per solved patch");
  const auto indexOf = [&](const SolvedPatch& p) {
    for (size_t i = 0; i < solved.size(); ++i)
      if (&solved[i] == &p) return i;
    throw Error(ErrorCode::UnknownName, "no solved patch named '" + p.patch->name + "'");
  };
  const EdgeReader readFaces = [&](const SolvedPatch& p, bool alongU, int end, const std::vector<double>& at) {
    const size_t i = indexOf(p);
    return fittedEdge(fits[i].surface, p.surface, alongU, end, at);
  };
  const std::vector<JoinResult> surfaces = certifyJoins(scene, solved);
  const std::vector<JoinResult> faces = certifyJoins(scene, solved, readFaces);
  const auto deviationOf = [&](const std::string& name) {
    for (size_t i = 0; i < solved.size(); ++i)
      if (solved[i].patch->name == name) return fits[i].report.deviation;
    return 0.0;
  };
  std::vector<FittedJoin> out;
  for (size_t k = 0; k < faces.size(); ++k) {
    FittedJoin j{faces[k], surfaces[k].g0 * surfaces[k].size, 0.0, faces[k].level >= 1 ? normalToleranceDeg : 180.0};
    j.allowedGap = j.surfacesGap + deviationOf(faces[k].patch) + deviationOf(faces[k].surface);
    // The gap within what the two certificates allow (a rounding's slack); normals within the
    // target where the join promises a tangent plane; no fold.
    const double size = faces[k].size;
    j.faces.ok = j.faces.g0 * size <= j.allowedGap * (1 + 1e-9) + 1e-15 * size && !j.faces.fold &&
                 (faces[k].level < 1 || j.faces.g1Deg <= normalToleranceDeg);
    out.push_back(j);
  }
  return out;
}

}  // namespace pdesurf
