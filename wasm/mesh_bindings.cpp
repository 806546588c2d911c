// modelMesh(sceneJson, nu, nv): the model's watertight mesh (analysis/watertight_mesh.hpp) for
// the page's mesh exports: one vertex array shared by the patches, each patch's triangles, and
// the bodies they form (docs/wasm-api.md). No exception crosses into JS.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cmath>

#include "analysis/bodies.hpp"
#include "analysis/report_json.hpp"
#include "analysis/join_certificate.hpp"
#include "analysis/watertight_mesh.hpp"
#include "common/errors.hpp"
#include "js_values.hpp"
#include "scene/scene.hpp"
#include "surface/tabulation.hpp"

using emscripten::val;
using namespace pdesurf;
using pdesurf::wasm::copyOut;
using pdesurf::wasm::gridArg;
using pdesurf::wasm::guarded;

namespace {

val modelMesh(const std::string& sceneJson, const val& nuArg, const val& nvArg) {
  return guarded("try a smaller grid", [&]() -> val {
    const int nu = gridArg(nuArg, "nu"), nv = gridArg(nvArg, "nv");
    checkGrid(nu, nv);
    const Scene scene = parseScene(sceneJson);
    checkSceneGrid(scene, nu, nv);
    const auto solved = solveScene(scene);
    const double size = sceneSizeOf(solved);
    const ModelMesh m = watertightMesh(solved, size, nu, nv);
    val parts = val::array();
    for (const ModelMesh::Part& p : m.parts) {
      val o = val::object();
      o.set("name", p.name);
      o.set("body", p.body);
      o.set("indices", copyOut(p.indices));
      parts.call<void>("push", o);
    }
    val bodies = val::array();
    for (const Body& b : measureBodies(solved, size)) bodies.call<void>("push", wasm::jsonValue(bodyJson(b)));  // as the report has them
    val out = val::object();
    out.set("ok", true);
    out.set("title", scene.title);
    out.set("positions", copyOut(m.positions));
    out.set("normals", copyOut(m.normals));
    out.set("parts", parts);
    out.set("bodies", bodies);
    return out;
  });
}

}  // namespace

EMSCRIPTEN_BINDINGS(pdesurf_mesh) { emscripten::function("modelMesh", &modelMesh); }
