// exportCad(sceneJson, options): every patch as a certified B-spline face (cpp/cad/), and the
// STEP or IGES text of them, as plain data (docs/wasm-api.md). The page runs it in its worker;
// the faces also feed the .3dm writer (web/cad/). No exception crosses into JS.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cmath>
#include <new>

#include "cad/border_joins.hpp"
#include "cad/brep_3dm.hpp"
#include "cad/brep_topology.hpp"
#include "cad/fitted_joins.hpp"
#include "cad/iges_writer.hpp"
#include "cad/scene_fit.hpp"
#include "cad/step_writer.hpp"
#include "common/errors.hpp"
#include "js_values.hpp"
#include "scene/scene.hpp"

using emscripten::val;
using namespace pdesurf;
using pdesurf::wasm::copyOut;
using pdesurf::wasm::guarded;

namespace {

val faceOf(const PatchFit& f) {
  const BSplineSurface& s = f.surface;
  val o = val::object();
  o.set("name", s.name);
  o.set("degreeU", s.degreeU);
  o.set("degreeV", s.degreeV);
  o.set("countU", s.countU);
  o.set("countV", s.countV);
  o.set("knotsU", copyOut(s.knotsU));
  o.set("knotsV", copyOut(s.knotsV));
  o.set("poles", copyOut(wasm::flattenExact(s.poles)));
  o.set("closedV", s.closedV);
  val degenerate = val::array();
  for (bool d : s.degenerate) degenerate.call<void>("push", d);
  o.set("degenerate", degenerate);
  o.set("exact", f.report.exact);
  o.set("deviation", f.report.deviation);
  o.set("sampledDeviation", f.report.sampledDeviation);
  o.set("normalDeviationDeg", f.report.normalDeviationDeg);
  o.set("normalsMet", f.report.normalsMet);
  return o;
}

// options: {format: "step" | "iges" | "3dm" | "faces" ("3dm": the faces and each body as one
// openNURBS Brep, web/cad/write-3dm.js), tolerance: number (absolute; absent or 0: the
// default, 1e-6 of the scene's diagonal), degree: 3 | 5, onProgress(done, total, patch): called
// after each patch's fit}.
val exportCad(const std::string& sceneJson, val options) {
  return guarded("try a larger tolerance", [&]() -> val {
    const bool isObject = !options.isUndefined() && !options.isNull() && options.typeOf().as<std::string>() == "object";
    std::string format = "faces";
    SceneFitOptions fit;
    if (isObject) {
      const val f = options["format"], t = options["tolerance"], d = options["degree"], progress = options["onProgress"];
      if (!progress.isUndefined()) {
        if (progress.typeOf().as<std::string>() != "function") throw Error(ErrorCode::InvalidField, "onProgress: must be a function");
        fit.progress = [progress](size_t done, size_t total, const std::string& patch) { progress(double(done), double(total), patch); };
      }
      if (!f.isUndefined()) {
        if (f.typeOf().as<std::string>() != "string") throw Error(ErrorCode::InvalidField, "format: must be \"step\", \"iges\", \"3dm\" or \"faces\"");
        format = f.as<std::string>();
        if (format != "step" && format != "iges" && format != "3dm" && format != "faces")
          throw Error(ErrorCode::InvalidField, "format: must be \"step\", \"iges\", \"3dm\" or \"faces\"");
      }
      if (!t.isUndefined()) {
        if (t.typeOf().as<std::string>() != "number" || !(t.as<double>() >= 0) || !std::isfinite(t.as<double>()))
          throw Error(ErrorCode::InvalidField, "tolerance: must be a positive finite number (0 or absent: the default)");
        fit.tolerance = t.as<double>();
      }
      if (!d.isUndefined()) {
        if (d.typeOf().as<std::string>() != "number" || (d.as<double>() != 3 && d.as<double>() != 5))
          throw Error(ErrorCode::InvalidField, "degree: must be 3 or 5");
        fit.degree = int(d.as<double>());
      }
    }
    const Scene scene = parseScene(sceneJson);
    const auto solved = solveScene(scene);
    double tolerance = 0;
    const std::vector<PatchFit> fits = fitScene(solved, fit, &tolerance);
    val faces = val::array();
    std::vector<BSplineSurface> surfaces;
    for (const PatchFit& f : fits) {
      faces.call<void>("push", faceOf(f));
      surfaces.push_back(f.surface);
    }
    // The joins between the faces, as `pdesurf export` prints them (cad/fitted_joins.hpp).
    val joins = val::array();
    for (const FittedJoin& j : certifyFittedJoins(scene, solved, fits)) {
      val o = val::object();
      o.set("patch", j.faces.patch);
      o.set("end", j.faces.end);
      o.set("surface", j.faces.surface);
      o.set("edge", j.faces.edge);
      o.set("level", std::string(levelName(j.faces.level)));
      o.set("gap", j.faces.g0 * j.faces.size);
      o.set("allowedGap", j.allowedGap);
      o.set("normalDeg", j.faces.g1Deg);
      o.set("ok", j.faces.ok);
      joins.call<void>("push", o);
    }
    val r = val::object();
    r.set("ok", true);
    r.set("title", scene.title);
    r.set("tolerance", tolerance);
    r.set("faces", faces);
    r.set("joins", joins);
    if (format != "faces") {
      CadFileInfo info;
      info.title = scene.title;
      info.tolerance = tolerance;
      // Every join one shared edge, closed shells as solids (cad/brep_topology.hpp).
      const BrepTopology topology = buildTopology(surfaces, borderJoins(solved), tolerance);
      if (format == "3dm") {
        // Each body one joined Brep, as openNURBS archive bytes for rhino3dm's decode().
        val breps = val::array();
        for (const OnBrepBody& b : onBreps(surfaces, topology)) {
          val o = val::object();
          o.set("closed", b.closed);
          o.set("faces", copyOut(b.faces));
          o.set("data", copyOut(std::vector<unsigned char>(b.bytes.begin(), b.bytes.end())));
          breps.call<void>("push", o);
        }
        r.set("breps", breps);
        r.set("archive3dm", kOn3dmVersion);
        r.set("opennurbs", double(kOnOpenNurbsVersion));
      } else {
        r.set("text", format == "step" ? writeStep(surfaces, info, &topology) : writeIges(surfaces, info, &topology));
      }
      val shells = val::array();
      for (const BrepShell& sh : topology.shells) {
        val o = val::object();
        o.set("faces", int(sh.faces.size()));
        o.set("closed", sh.closed);
        o.set("volume", sh.volume);
        shells.call<void>("push", o);
      }
      r.set("shells", shells);
    }
    return r;
  });
}

}  // namespace

EMSCRIPTEN_BINDINGS(pdesurf_cad) { emscripten::function("exportCad", &exportCad); }
