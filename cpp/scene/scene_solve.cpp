#include <memory>
#include <string>

#include "common/errors.hpp"
#include "bezier/bezier_solver.hpp"
#include "methods/method.hpp"
#include "scene/scene.hpp"
#include "surface/tabulation.hpp"

namespace pdesurf {

const Patch* Scene::find(const std::string& name) const {
  for (const Patch& p : patches)
    if (p.name == name) return &p;
  return nullptr;
}

const Patch* Scene::firstSolved() const {
  if (const Patch* p = firstPde()) return p;
  for (const Patch& p : patches)
    if (p.kind == PatchKind::Bezier) return &p;
  return nullptr;
}

const Patch* Scene::firstPde() const {
  for (const Patch& p : patches)
    if (p.kind == PatchKind::Pde) return &p;
  return nullptr;
}

void checkSceneGrid(const Scene& scene, int nu, int nv) {
  checkGrid(nu, nv);
  const size_t perPatch = static_cast<size_t>(nu + 1) * (nv + 1), total = perPatch * scene.patches.size();
  if (total > limits::kSceneVertices)
    throw Error(ErrorCode::TooLarge, std::to_string(scene.patches.size()) + " patches on a " + std::to_string(nu) + "x" + std::to_string(nv) +
                                         " grid make " + std::to_string(total) + " vertices, over the " +
                                         std::to_string(limits::kSceneVertices) + " a scene may draw at once");
}

namespace {

// T(t) as a u-factor: cos and sin are the real parts of complex exponentials, cosh and sinh
// sums of two real ones.
UFactor tFactor(const VFunction& f, double coef) {
  UFactor out;
  auto piece = [&](cplx rate, cplx c) {
    ExpPoly p;
    p.rate = rate;
    p.poly = {c};
    out.pieces.push_back(p);
  };
  const double w = f.w;
  switch (f.family) {
    case Family::Poly: {
      std::vector<double> poly(f.n + 1, 0.0);
      poly[f.n] = coef;
      return UFactor::polynomial(poly);
    }
    case Family::Cos: piece(cplx(0, w), coef); break;
    case Family::Sin: piece(cplx(0, w), cplx(0, -coef)); break;
    case Family::Exp: piece(w, coef); break;
    case Family::Cosh: piece(w, coef / 2), piece(-w, coef / 2); break;
    case Family::Sinh: piece(w, coef / 2), piece(-w, -coef / 2); break;
    case Family::General:
    case Family::Bernstein: throw Error(ErrorCode::Internal, "a factor of t must be a basis function");
  }
  return out;
}

SeparableSurface primaryToSeparable(const PrimarySurface& p) {
  SeparableSurface s;
  s.u0 = p.t0;
  s.u1 = p.t1;
  s.v0 = p.v0;
  s.v1 = p.v1;
  for (int c = 0; c < 3; ++c)
    for (const PrimaryTerm& t : p.terms[c]) s.component[c].push_back({t.v, tFactor(t.t, t.coef)});
  s.pointwise = p.pointwise;
  s.pointwisePartials = p.pointwisePartials;
  return s;
}

}  // namespace

SolvedPatch solvePatch(const Patch& patch, const Method* method, SolveCache* cache) {
  try {
    if (patch.kind == PatchKind::Primary) return {&patch, primaryToSeparable(patch.primary), Method{}, {}, 0.0, 0.0};
    if (patch.kind == PatchKind::Bezier) {
      std::unique_ptr<BezierSolver> own;
      if (!cache) own = std::make_unique<BezierSolver>(patch.bezier);
      const BezierSolver& solver = cache ? cache->bezier.get(patch.bezier) : *own;
      SolvedPatch out{&patch, {}, Method{}, solver.solve(patch.bezier.initial), 0.0, 0.0};
      out.surface = bezierToSeparable(patch.bezier.n, patch.bezier.m, out.controlNet);
      out.energy = solver.energy(out.controlNet, patch.bezier.initial);
      out.normalMisfit = solver.normalMisfit(out.controlNet);
      return out;
    }
    MethodSolution m = solveWithMethod(patch.pde, method ? *method : patch.method, cache ? &cache->bases : nullptr);
    return {&patch, std::move(m.surface), m.used, {}, 0.0, 0.0};
  } catch (const Error& e) {
    throw Error(e.code(), "patch '" + patch.name + "': " + e.what());
  }
}

std::vector<SolvedPatch> solveScene(const Scene& scene, SolveCache* cache) {
  std::vector<SolvedPatch> out;
  for (const Patch& p : scene.patches) out.push_back(solvePatch(p, nullptr, cache));
  return out;
}

}  // namespace pdesurf
