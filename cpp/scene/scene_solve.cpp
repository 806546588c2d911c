#include <Eigen/Eigenvalues>
#include <memory>
#include <string>

#include "common/errors.hpp"
#include "bezier/bezier_solver.hpp"
#include "common/text.hpp"
#include "methods/measures.hpp"
#include "methods/method.hpp"
#include "analysis/fill_centre.hpp"
#include "basis/general_function.hpp"
#include "scene/chain_conditions.hpp"
#include "scene/scene.hpp"
#include "surface/same_surface.hpp"
#include "surface/tabulation.hpp"

namespace pdesurf {

const Patch* Scene::find(const std::string& name) const {
  for (const Patch& p : patches)
    if (p.name == name) return &p;
  return nullptr;
}

const Patch* Scene::firstSolved() const {
  if (const Patch* p = firstPde()) return p;
  return firstBezier();
}

const Patch* Scene::firstBezier() const {
  for (const Patch& p : patches)
    if (p.kind == PatchKind::Bezier) return &p;
  return nullptr;
}

const Patch* Scene::firstPde() const {
  for (const Patch& p : patches)
    if (p.solvedAsPde()) return &p;
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
  // Its non-separable part's partials built and compiled once, for every tabulation after.
  for (int c = 0; c < 3; ++c) {
    if (!s.pointwise[c]) continue;
    if (s.pointwisePartials[c].size() < 6) s.pointwisePartials[c] = partialDerivatives(s.pointwise[c], true);
    s.pointwisePrograms[c] = std::make_shared<const ExprProgram>(s.pointwisePartials[c]);
  }
  return s;
}

}  // namespace

namespace {

constexpr double kBoundaryMiss = 1e-6;

bool sameExpansion(const VExpansion& a, const VExpansion& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].coef != b[i].coef || !sameFunction(a[i].g, b[i].g)) return false;
  return true;
}

bool sameSlots(const std::vector<VExpansion>& a, const std::vector<VExpansion>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (!sameExpansion(a[i], b[i])) return false;
  return true;
}

bool sameProblem(const PdeProblem& a, const PdeProblem& b) {
  if (a.v0 != b.v0 || a.v1 != b.v1) return false;
  for (int c = 0; c < 3; ++c) {
    const ComponentProblem &x = a.component[c], &y = b.component[c];
    if (x.alpha != y.alpha || !sameSlots(x.left, y.left) || !sameSlots(x.right, y.right)) return false;
    if (x.force.size() != y.force.size() || x.generalForce.size() != y.generalForce.size()) return false;
    for (size_t i = 0; i < x.force.size(); ++i)
      if (x.force[i].uPoly != y.force[i].uPoly || !sameFunction(x.force[i].g, y.force[i].g)) return false;
    for (size_t i = 0; i < x.generalForce.size(); ++i)
      if (x.generalForce[i].f != y.generalForce[i].f) return false;
  }
  return true;
}

bool sameMethod(const Method& a, const Method& b) {
  return a.kind == b.kind && a.terms == b.terms && a.navierM == b.navierM && a.navierN == b.navierN && a.navierPoints == b.navierPoints;
}

SolvedPatch solveWith(const Patch& patch, std::shared_ptr<const PdeProblem> problem, const Method* method, SolveCache* cache) {
  if (!patch.solvedAsPde()) return solvePatch(patch, method, cache);
  const PdeProblem& pde = problem ? *problem : patch.pde();
  const Method& m = method ? *method : patch.method();
  if (cache) {
    const auto it = cache->solved.find(patch.name);
    if (it != cache->solved.end() && sameMethod(it->second.method, m) && sameProblem(it->second.problem, pde)) {
      SolvedPatch out{&patch, it->second.surface, it->second.used, {}, 0.0, 0.0, problem, true, it->second.id};
      return out;
    }
  }
  try {
    MethodSolution solution = solveWithMethod(pde, m, cache ? &cache->bases : nullptr);
    // Every method meets its boundary data exactly by construction; one that did not (a force
    // beyond its expansion, rounding run away) must not be drawn as if it had.
    // So far only forces were found to do it (docs/limits.md): the check runs where there is one.
    bool forced = false;
    for (const ComponentProblem& c : pde.component) forced = forced || !c.force.empty() || !c.generalForce.empty();
    if (forced && m.kind != MethodKind::Fourier && m.kind != MethodKind::PseudoSpectral) {
      const double missed = boundaryConditionError(pde, solution.surface, 32);
      if (std::isfinite(missed) && missed > kBoundaryMiss)
        throw Error(ErrorCode::Singular, methodName(solution.used) + " missed the boundary conditions by " + numberText(missed) +
                                             " (relative): the data or the force are beyond what it can expand; try another method");
    }
    if (patch.isFill()) checkFillRegular(patch, solution.surface);
    SolvedPatch out{&patch, std::move(solution.surface), solution.used, {}, 0.0, 0.0, problem, false};
    if (cache) {
      out.solveId = ++cache->solves;
      cache->solved[patch.name] = SolveMemo{pde, m, out.surface, out.used, out.solveId};
    }
    return out;
  } catch (const Error& e) {
    throw Error(e.code(), "patch '" + patch.name + "': " + e.what());
  }
}

// The points lie on a line or at one point (to rounding): a Bézier surface stays in its net's
// convex hull, so it has no area.
bool spansNoArea(const std::vector<Eigen::Vector3d>& net) {
  double reach = 0.0;  // the coordinates' size: rounding's scale (points scaled by it: no overflow)
  for (const Eigen::Vector3d& p : net) reach = std::max(reach, p.lpNorm<Eigen::Infinity>());
  if (!std::isfinite(reach)) return false;  // not finite: named where it is drawn
  if (reach == 0.0) return true;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : net) mean += p / reach;
  mean /= double(net.size());
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : net) spread += (p / reach - mean) * (p / reach - mean).transpose();
  const Eigen::Vector3d e = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(spread, Eigen::EigenvaluesOnly).eigenvalues();  // ascending
  // At a point (the spread within rounding of the coordinates), or on a line (the second
  // spread direction within 1e-12 of the first, in length).
  return !(std::sqrt(e(2)) > 1e-12) || !(e(1) > 1e-24 * e(2));
}

}  // namespace

SolvedPatch solvePatch(const Patch& patch, const Method* method, SolveCache* cache) {
  try {
    if (!patch.dependsOn.empty())
      throw Error(ErrorCode::InvalidField, "its conditions come from '" + patch.dependsOn.front() + "': solve it with the scene");
    if (patch.kind == PatchKind::Primary) return {&patch, primaryToSeparable(patch.primary()), Method{}, {}, 0.0, 0.0};
    if (patch.kind == PatchKind::Bezier) {
      std::unique_ptr<BezierSolver> own;
      if (!cache) own = std::make_unique<BezierSolver>(patch.bezier());
      const BezierSolver& solver = cache ? cache->bezier.get(patch.bezier()) : *own;
      SolvedPatch out{&patch, {}, Method{}, solver.solve(patch.bezier().initial), 0.0, 0.0};
      if (spansNoArea(out.controlNet))
        throw Error(ErrorCode::InvalidField, "its solved control net lies on a line or at a point: the surface has no area (give a net or borders that span one)");
      out.surface = bezierToSeparable(patch.bezier().n, patch.bezier().m, out.controlNet);
      out.energy = solver.energy(out.controlNet, patch.bezier().initial);
      out.normalMisfit = solver.normalMisfit(out.controlNet);
      return out;
    }
    MethodSolution m = solveWithMethod(patch.pde(), method ? *method : patch.method(), cache ? &cache->bases : nullptr);
    return {&patch, std::move(m.surface), m.used, {}, 0.0, 0.0};
  } catch (const Error& e) {
    throw Error(e.code(), "patch '" + patch.name + "': " + e.what());
  }
}

namespace {

// Solves `wanted` (indices, each after what it depends on) into `out` (by index).
void solveInOrder(const Scene& scene, const std::vector<size_t>& wanted, std::vector<std::unique_ptr<SolvedPatch>>& out, SolveCache* cache,
                  const Patch* overridden, const Method* method) {
  const SolvedLookup lookup = [&](const std::string& name) -> const SolvedPatch& {
    for (size_t i = 0; i < scene.patches.size(); ++i)
      if (scene.patches[i].name == name && out[i]) return *out[i];
    throw Error(ErrorCode::Internal, "'" + name + "' is not solved yet");
  };
  size_t derivedNodes = 0;  // summed over the solve (limits::kSceneDerivedNodes)
  for (size_t i : wanted) {
    const Patch& p = scene.patches[i];
    std::shared_ptr<const PdeProblem> problem;
    if (!p.dependsOn.empty()) problem = inPatch(p.name, [&] { return derivedProblem(p, lookup, &derivedNodes); });
    out[i] = std::make_unique<SolvedPatch>(solveWith(p, problem, &p == overridden ? method : nullptr, cache));
  }
}

}  // namespace

std::vector<SolvedPatch> solveScene(const Scene& scene, SolveCache* cache) {
  if (cache)  // the memo keeps this scene's patches only
    for (auto it = cache->solved.begin(); it != cache->solved.end();) it = scene.find(it->first) ? std::next(it) : cache->solved.erase(it);
  std::vector<std::unique_ptr<SolvedPatch>> byIndex(scene.patches.size());
  solveInOrder(scene, scene.solveOrder, byIndex, cache, nullptr, nullptr);
  std::vector<SolvedPatch> out;
  for (auto& s : byIndex) out.push_back(std::move(*s));
  return out;
}

SolvedPatch solvePatchIn(const Scene& scene, const Patch& patch, const Method* method) {
  if (patch.dependsOn.empty()) return solvePatch(patch, method);
  // What it needs: the patches before it in solveOrder it reaches through dependsOn.
  std::vector<bool> needed(scene.patches.size(), false);
  size_t target = 0;
  while (&scene.patches[target] != &patch) ++target;
  needed[target] = true;
  std::vector<size_t> order;
  for (auto it = scene.solveOrder.rbegin(); it != scene.solveOrder.rend(); ++it) {
    if (!needed[*it]) continue;
    order.insert(order.begin(), *it);
    for (const std::string& d : scene.patches[*it].dependsOn)
      for (size_t i = 0; i < scene.patches.size(); ++i)
        if (scene.patches[i].name == d) needed[i] = true;
  }
  std::vector<std::unique_ptr<SolvedPatch>> byIndex(scene.patches.size());
  solveInOrder(scene, order, byIndex, nullptr, &patch, method);
  return std::move(*byIndex[target]);
}

void tessellatePatchInto(const SolvedPatch& patch, int nu, int nv, Mesh& out, bool curvature) {
  try {
    tessellateInto(patch.surface, nu, nv, out, curvature);
  } catch (const Error& e) {
    // The drawing names a point (t, v), a surface's parameters; a pde or Bézier patch's are (u, v).
    std::string what = e.what();
    if (patch.patch->kind != PatchKind::Primary)
      for (size_t at; (at = what.find("(t, v)")) != std::string::npos;) what.replace(at, 6, "(u, v)");
    throw Error(e.code(), "patch '" + patch.patch->name + "': " + what);
  }
}

Mesh tessellatePatch(const SolvedPatch& patch, int nu, int nv, bool curvature) {
  Mesh m;
  tessellatePatchInto(patch, nu, nv, m, curvature);
  return m;
}

}  // namespace pdesurf
