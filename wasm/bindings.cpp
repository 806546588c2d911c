// embind bindings: the only platform code of the wasm build. Every call returns plain data
// ({ok, patches} or {ok: false, error: {code, message}}); no exception crosses into JS, so
// the module never aborts and holds no long-lived objects that JS would have to delete().
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <new>

#include "bezier/bernstein.hpp"
#include "common/errors.hpp"
#include "ode/basis_cache.hpp"
#include "scene/scene.hpp"
#include "surface/mesh.hpp"
#include "surface/tabulation.hpp"

using emscripten::val;
using namespace pdesurf;

namespace {

// A copy, not a view: views into the wasm heap go stale when the heap grows.
template <class T>
val copyOut(const std::vector<T>& v) {
  return val(emscripten::typed_memory_view(v.size(), v.data())).call<val>("slice");
}

// Per coordinate: {order, params: {name: value}} with the scene's own names (s, t / b, c, d /
// a / coefficients[k]), so the page can show and edit them.
val operatorOf(const Patch& p) {
  val op = val::object();
  const char* axis[3] = {"x", "y", "z"};
  for (int c = 0; c < 3; ++c) {
    val comp = val::object();
    comp.set("order", p.op[c].order);
    val params = val::object();
    for (size_t k = 0; k < p.op[c].names.size(); ++k) params.set(p.op[c].names[k], p.op[c].values[k]);
    comp.set("params", params);
    op.set(axis[c], comp);
  }
  return op;
}

std::vector<float> flatten(const std::vector<Eigen::Vector3d>& pts) {
  std::vector<float> out;
  for (const auto& q : pts) out.insert(out.end(), {static_cast<float>(q.x()), static_cast<float>(q.y()), static_cast<float>(q.z())});
  return out;
}

// Seed 002 patches: the solved and initial control nets, the guiding normals as arrows on the
// solved surface, the energy and the normal misfit.
void setBezierExtras(val& p, const SolvedPatch& sp) {
  const BezierProblem& b = sp.patch->bezier;
  p.set("netSize", val::array(std::vector<int>{b.n + 1, b.m + 1}));
  p.set("controlNet", copyOut(flatten(sp.controlNet)));
  p.set("initialNet", copyOut(flatten(b.initial)));
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

val failure(const char* code, const std::string& message) {
  val err = val::object();
  err.set("code", std::string(code));
  err.set("message", message);
  val r = val::object();
  r.set("ok", false);
  r.set("error", err);
  return r;
}

val solveSceneJs(const std::string& sceneJson, int nu, int nv) {
  try {
    checkGrid(nu, nv);
    const Scene scene = parseScene(sceneJson);
    // Kept between calls: a slider that moves a trimline reuses every ODE basis, a drag of a
    // Bézier control point its factorisation.
    static SolveCache cache;
    const auto solved = solveScene(scene, &cache);
    // Meshes are kept between calls: a slider drag re-solves at the same grid, so the
    // buffers, uvs and indices are reused instead of rebuilt.
    static std::vector<Mesh> meshes;
    if (meshes.size() < solved.size()) meshes.resize(solved.size());
    val patches = val::array();
    for (size_t k = 0; k < solved.size(); ++k) {
      const SolvedPatch& sp = solved[k];
      Mesh& m = meshes[k];
      try {
        tessellateInto(sp.surface, nu, nv, m);
      } catch (const Error& e) {
        throw Error(e.code(), "patch '" + sp.patch->name + "': " + e.what());
      }
      val p = val::object();
      p.set("name", sp.patch->name);
      p.set("kind", sp.patch->kindName);
      if (sp.patch->kind == PatchKind::Pde) {
        p.set("operator", operatorOf(*sp.patch));
        p.set("method", methodName(sp.used));
        val methods = val::array();
        for (const std::string& m : applicableMethods(sp.patch->pde)) methods.call<void>("push", m);
        p.set("methods", methods);
      }
      if (sp.patch->kind == PatchKind::Bezier) setBezierExtras(p, sp);
      p.set("positions", copyOut(m.positions));
      p.set("normals", copyOut(m.normals));
      p.set("uvs", copyOut(m.uvs));
      p.set("indices", copyOut(m.indices));
      patches.call<void>("push", p);
    }
    val r = val::object();
    r.set("ok", true);
    r.set("title", scene.title);
    r.set("patches", patches);
    return r;
  } catch (const Error& e) {
    return failure(errorCodeName(e.code()), e.what());
  } catch (const std::bad_alloc&) {
    return failure("Internal", "out of memory: try a smaller grid");
  } catch (const std::exception& e) {
    return failure("Internal", e.what());
  }
}

std::string version() { return "0.1.0"; }

}  // namespace

EMSCRIPTEN_BINDINGS(pdesurf) {
  emscripten::function("solveScene", &solveSceneJs);
  emscripten::function("version", &version);
}
