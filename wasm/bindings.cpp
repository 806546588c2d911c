// embind bindings: the only platform code of the wasm build. Every call returns plain data
// ({ok, patches} or {ok: false, error: {code, message}}); no exception crosses into JS, so
// the module never aborts and holds no long-lived objects that JS would have to delete().
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cmath>
#include <new>

#include "analysis/bodies.hpp"
#include "analysis/join_certificate.hpp"
#include "bezier/bernstein.hpp"
#include "common/errors.hpp"
#include "ode/basis_cache.hpp"
#include "scene/patch_kinds.hpp"
#include "scene/scene.hpp"
#include "surface/mesh.hpp"
#include "surface/tabulation.hpp"
#include "js_values.hpp"
#include "kept_solve.hpp"
#include "report_values.hpp"

using emscripten::val;
using namespace pdesurf;
using pdesurf::wasm::copyOut;
using pdesurf::wasm::gridArg;
using pdesurf::wasm::guarded;

namespace {

// Per coordinate: {order, params: {name: value}} with the scene's own names (s, t / b, c, d /
// a / coefficients[k]), so the page can show and edit them.
val operatorOf(const Patch& p) {
  val op = val::object();
  const char* axis[3] = {"x", "y", "z"};
  for (int c = 0; c < 3; ++c) {
    val comp = val::object();
    comp.set("order", p.op()[c].order);
    val params = val::object();
    for (size_t k = 0; k < p.op()[c].names.size(); ++k) params.set(p.op()[c].names[k], p.op()[c].values[k]);
    comp.set("params", params);
    op.set(axis[c], comp);
  }
  return op;
}

// Ends given by reference (scene version 3): {u0: {surface, derived: {x: [X, X_u, …], y, z}}, …}
// with the derived conditions as text, for the page's blend panel (read-only, or detached).
val endsOf(const Patch& p) {
  val ends = val::object();
  for (int end = 0; end < 2; ++end) {
    const EndReference& e = p.ends()[end];
    if (!e.given) continue;
    val o = val::object();
    if (!e.patch.empty()) {  // a chain (version 4): its conditions are derived when solved
      o.set("patch", e.patch);
      o.set("at", std::string(kBezierEdge[e.patchEdge]));
      ends.set(end ? "u1" : "u0", o);
      continue;
    }
    o.set("surface", e.surface);
    val derived = val::object();
    const char* axis[3] = {"x", "y", "z"};
    for (int c = 0; c < 3; ++c) {
      val list = val::array();
      for (const std::string& t : e.derived[c]) list.call<void>("push", t);
      derived.set(axis[c], list);
    }
    o.set("derived", derived);
    ends.set(end ? "u1" : "u0", o);
  }
  return ends;
}

std::vector<float> flatten(const std::vector<Eigen::Vector3d>& pts) {
  std::vector<float> out;
  for (const auto& q : pts) out.insert(out.end(), {static_cast<float>(q.x()), static_cast<float>(q.y()), static_cast<float>(q.z())});
  return out;
}

// Seed 002 patches: the solved and initial control nets, the guiding normals as arrows on the
// solved surface, the energy and the normal misfit.
void setBezierExtras(val& p, const SolvedPatch& sp) {
  const BezierProblem& b = sp.patch->bezier();
  p.set("netSize", val::array(std::vector<int>{b.n + 1, b.m + 1}));
  // The nets in doubles: a detached border is typed from them exactly (web/state/patch-delete.js).
  p.set("controlNet", copyOut(wasm::flattenExact(sp.controlNet)));
  p.set("initialNet", copyOut(wasm::flattenExact(b.initial)));
  p.set("energy", sp.energy);
  p.set("normalMisfit", sp.normalMisfit);
  p.set("lambda", b.lambda);
  p.set("gamma", b.gamma);
  // Arrows: at the discrete samples (at most 17×17 of them) or on a 9×9 grid of the field.
  std::vector<Eigen::Vector3d> at, dir;
  const BezierNormalField& f = b.normals;
  const int nu = f.discrete ? f.np : 8, nv = f.discrete ? f.mp : 8;
  const int su = std::max(1, nu / 16), sv = std::max(1, nv / 16);
  for (int i = 0; i <= nu; i += su)
    for (int j = 0; j <= nv; j += sv) {
      const double u = static_cast<double>(i) / nu, v = static_cast<double>(j) / nv;
      at.push_back(evalPoint(sp.surface, u, v));
      Eigen::Vector3d d = Eigen::Vector3d::Zero();
      if (f.discrete) {
        d = f.vectors[i * (f.mp + 1) + j].normalized();
      } else {
        const auto bu = bernstein(f.n1, u), bv = bernstein(f.m1, v);
        for (int a = 0; a <= f.n1; ++a)
          for (int c = 0; c <= f.m1; ++c) d += bu[a] * bv[c] * f.vectors[a * (f.m1 + 1) + c];
      }
      dir.push_back(d);
    }
  p.set("normalOrigins", copyOut(flatten(at)));
  p.set("normalVectors", copyOut(flatten(dir)));
}

// The join certificate as plain data (docs/wasm-api.md); crossings, on a 48×48 mesh per patch,
// only when asked: they cost several times a re-solve. All at once, in the solve's call (the
// page asks for it part by part instead: report_bindings.cpp).
val reportOf(const Scene& scene, const std::vector<SolvedPatch>& solved, bool crossings) {
  try {
    const SceneReport r = checkScene(scene, solved, crossings ? 48 : 0);
    return wasm::reportValue(r, measureBodies(solved, r.sceneSize), crossings);
  } catch (const Error& e) {
    return wasm::reportFailure(e, crossings);
  }
}

// What a kept mesh was made from: a pde patch's memoised solve (SolvedPatch::solveId) on a grid.
struct MeshSource {
  uint64_t solve = 0;  // 0: not reusable
  int nu = 0, nv = 0;
  bool curvature = false;
  bool operator==(const MeshSource& o) const { return solve != 0 && solve == o.solve && nu == o.nu && nv == o.nv && curvature == o.curvature; }
};

val solveSceneJs(const std::string& sceneJson, const val& nuArg, const val& nvArg, bool curvature, bool joins, bool crossings,
                 bool topology) {
  return guarded("try a smaller grid", [&]() -> val {
    const int nu = gridArg(nuArg, "nu"), nv = gridArg(nvArg, "nv");
    checkGrid(nu, nv);
    auto kept = std::make_shared<const Scene>(parseScene(sceneJson));
    const Scene& scene = *kept;
    checkSceneGrid(scene, nu, nv);
    // Kept between calls: a slider that moves a trimline reuses every ODE basis, a drag of a
    // Bézier control point its factorisation.
    static SolveCache cache;
    auto keptSolved = std::make_shared<const std::vector<SolvedPatch>>(solveScene(scene, &cache));
    const std::vector<SolvedPatch>& solved = *keptSolved;
    // Meshes are kept between calls: a slider drag re-solves at the same grid, so the
    // buffers, uvs and indices are reused instead of rebuilt.
    static std::vector<Mesh> meshes;
    static std::vector<MeshSource> meshSources;
    if (meshes.size() < solved.size()) meshes.resize(solved.size());
    if (meshSources.size() < meshes.size()) meshSources.resize(meshes.size());
    val patches = val::array();
    for (size_t k = 0; k < solved.size(); ++k) {
      const SolvedPatch& sp = solved[k];
      Mesh& m = meshes[k];
      // A patch the cache did not solve again (an edit upstream of nothing it depends on) keeps
      // its mesh when that mesh was made from the same solve on the same grid.
      MeshSource& from = meshSources[k];
      const MeshSource now{sp.solveId, nu, nv, curvature};
      if (!(from == now)) {
        try {
          tessellatePatchInto(sp, nu, nv, m, curvature);
        } catch (const Error&) {
          from = MeshSource{};
          throw;
        }
      }
      from = now;
      val p = val::object();
      p.set("name", sp.patch->name);
      p.set("kind", sp.patch->kindName);
      if (!sp.patch->dependsOn.empty()) {  // the patches its conditions come from (the outliner's chain)
        val on = val::array();
        for (const std::string& d : sp.patch->dependsOn) on.call<void>("push", d);
        p.set("dependsOn", on);
      }
      p.set("reused", sp.reused);
      if (sp.patch->solvedAsPde()) {
        p.set("operator", operatorOf(*sp.patch));
        if (sp.patch->ends()[0].given || sp.patch->ends()[1].given) p.set("ends", endsOf(*sp.patch));
        p.set("method", methodName(sp.used));
        val methods = val::array();
        for (const std::string& m : applicableMethods(sp.patch->pde())) methods.call<void>("push", m);
        p.set("methods", methods);
      }
      if (sp.patch->kind == PatchKind::Bezier) setBezierExtras(p, sp);
      p.set("positions", copyOut(m.positions));
      p.set("normals", copyOut(m.normals));
      if (topology) {  // uvs and indices change only with the grid: the page asks when it did
        p.set("uvs", copyOut(m.uvs));
        p.set("indices", copyOut(m.indices));
      }
      if (curvature) {
        p.set("meanCurvature", copyOut(m.meanCurvature));
        p.set("gaussCurvature", copyOut(m.gaussCurvature));
        p.set("degenerateVertices", m.degenerateVertices);
      }
      patches.call<void>("push", p);
    }
    val r = val::object();
    r.set("ok", true);
    r.set("title", scene.title);
    r.set("patches", patches);
    if (joins) r.set("report", reportOf(scene, solved, crossings));
    // The last good solve, for its report part by part (reportBegin, reportStep): a solve that
    // failed above leaves the one drawn before.
    wasm::keepSolve(std::move(kept), std::move(keptSolved));
    // The wasm heap never shrinks; at least hand large meshes back to the allocator, so a
    // one-off big grid does not stay held by the cache (the next solve reuses the memory).
    if (static_cast<size_t>(nu + 1) * (nv + 1) > size_t{513} * 513) std::vector<Mesh>().swap(meshes), meshSources.clear();
    return r;
  });
}

val solveScenePlain(const std::string& sceneJson, val nu, val nv) { return solveSceneJs(sceneJson, nu, nv, false, false, false, true); }

// options: {curvature: bool, joins: bool, crossings: bool (only with joins), topology: bool
// (default true; false leaves out uvs and indices, which change only with the grid)};
// anything else (or a missing key) counts as false.
val solveSceneWith(const std::string& sceneJson, val nu, val nv, val options) {
  const auto flag = [&](const char* key) {
    if (options.isUndefined() || options.isNull() || options.typeOf().as<std::string>() != "object") return false;
    const val v = options[key];
    return v.typeOf().as<std::string>() == "boolean" && v.as<bool>();
  };
  const bool isObject = !options.isUndefined() && !options.isNull() && options.typeOf().as<std::string>() == "object";
  const bool topology = !(isObject && options["topology"].typeOf().as<std::string>() == "boolean" && !options["topology"].as<bool>());
  return solveSceneJs(sceneJson, nu, nv, flag("curvature"), flag("joins"), flag("crossings"), topology);
}

std::string version() { return "0.1.0"; }

// The core's table of patch kinds (scene/patch_kinds.hpp): [{ name, since, solvedAs }], for the
// test that the page's own table (web/state/patch-kinds.js) agrees with it.
val patchKindList() {
  val out = val::array();
  for (const PatchKindEntry& k : patchKinds()) {
    val o = val::object();
    o.set("name", std::string(k.name));
    o.set("since", k.since);
    o.set("solvedAs", std::string(k.solvedAs == PatchKind::Pde || k.solvedAs == PatchKind::Fill ? "pde" : k.solvedAs == PatchKind::Bezier ? "bezier" : "primary"));
    out.call<void>("push", o);
  }
  return out;
}

}  // namespace

EMSCRIPTEN_BINDINGS(pdesurf) {
  emscripten::function("solveScene", &solveScenePlain);
  emscripten::function("solveSceneWith", &solveSceneWith);
  emscripten::function("version", &version);
  emscripten::function("patchKinds", &patchKindList);
}
