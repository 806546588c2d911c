#include "cad/scene_fit.hpp"

#include <cmath>

#include "common/errors.hpp"

namespace pdesurf {

double sceneDiagonal(const std::vector<SolvedPatch>& solved) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(HUGE_VAL), hi = -lo;
  for (const SolvedPatch& sp : solved) {
    const SeparableSurface& s = sp.surface;
    for (int i = 0; i <= 32; ++i)
      for (int j = 0; j <= 32; ++j) {
        const Eigen::Vector3d x = evalPoint(s, s.u0 + (s.u1 - s.u0) * i / 32, s.v0 + (s.v1 - s.v0) * j / 32);
        if (x.allFinite()) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
      }
  }
  return solved.empty() || !(hi.x() >= lo.x()) ? 0.0 : (hi - lo).norm();
}

FitOptions resolveFitOptions(const std::vector<SolvedPatch>& solved, const SceneFitOptions& o) {
  // Before the tolerance: an empty scene's default tolerance would be 0 of nothing, and the
  // error blamed a tolerance nobody gave.
  if (solved.empty()) throw Error(ErrorCode::InvalidField, "patches: the scene has no patch to write as a CAD face");
  FitOptions fit;
  fit.degree = o.degree;
  fit.tolerance = o.tolerance;
  if (o.tolerance == 0.0) fit.tolerance = kDefaultFitTolerance * sceneDiagonal(solved);
  if (!(fit.tolerance > 0) || !std::isfinite(fit.tolerance))
    throw Error(ErrorCode::InvalidField, "tolerance: must be a positive finite number");
  return fit;
}

PatchFit fitPatch(const SolvedPatch& sp, const FitOptions& fit) {
  PatchFit f;
  try {
    if (sp.patch->kind == PatchKind::Bezier) {
      f.surface = bezierAsBSpline(sp.patch->bezier().n, sp.patch->bezier().m, sp.controlNet);
      f.report.exact = true;
    } else {
      f.surface = fitSurface(sp.surface, fit, &f.report);
    }
  } catch (const SceneWorkExceeded&) {
    throw;  // the scene's, not this patch's
  } catch (const Error& e) {
    throw Error(e.code(), "patch '" + sp.patch->name + "': " + e.what());
  }
  f.surface.name = sp.patch->name;
  return f;
}

std::vector<PatchFit> fitScene(const std::vector<SolvedPatch>& solved, const SceneFitOptions& o, double* tolerance) {
  FitOptions fit = resolveFitOptions(solved, o);
  if (tolerance) *tolerance = fit.tolerance;
  FitWork work;  // the scene's budget, summed over its patches
  if (!fit.work) fit.work = &work;
  std::vector<PatchFit> out;
  for (const SolvedPatch& sp : solved) {
    out.push_back(fitPatch(sp, fit));
    if (o.progress) o.progress(out.size(), solved.size(), sp.patch->name);
  }
  return out;
}

}  // namespace pdesurf
