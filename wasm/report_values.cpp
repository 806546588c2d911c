#include "report_values.hpp"

#include <string>

using emscripten::val;

namespace pdesurf::wasm {
namespace {

val joinObject(const JoinResult& j) {
  val o = val::object();
  o.set("patch", j.patch);
  o.set("end", j.end);
  o.set("surface", j.surface);
  o.set("edge", j.edge);
  o.set("level", std::string(levelName(j.level)));
  o.set("size", j.size);
  o.set("g0", j.g0);
  o.set("g1_deg", j.g1Deg);
  o.set("g2_rel", j.level == 2 ? val(j.g2Rel) : val::null());
  o.set("fold", j.fold);
  o.set("degenerate", j.degenerate);
  o.set("worstV", j.worstV);
  o.set("ok", j.ok);
  return o;
}

}  // namespace

val reportValue(const SceneReport& r, const std::vector<Body>& bodies, bool crossingsChecked) {
  val report = val::object();
  report.set("crossingsChecked", crossingsChecked);
  report.set("ok", r.ok);
  report.set("sceneSize", r.sceneSize);
  val joins = val::array(), seams = val::array();
  for (const JoinResult& j : r.joins) joins.call<void>("push", joinObject(j));
  // Closed patches joined to themselves across v0 = v1 (worstV: the u where it is worst).
  for (const JoinResult& j : r.seams) seams.call<void>("push", joinObject(j));
  report.set("seams", seams);
  report.set("joins", joins);
  val crossings = val::array();
  for (const Crossing& c : r.crossings) {
    val o = val::object();
    o.set("patch", c.patch);
    o.set("other", c.other);
    o.set("u", val::array(std::vector<double>{c.u[0], c.u[1]}));
    o.set("v", val::array(std::vector<double>{c.v[0], c.v[1]}));
    o.set("triangles", c.triangles);
    crossings.call<void>("push", o);
  }
  report.set("crossings", crossings);
  val centres = val::array();  // every fill's centre (version 4)
  for (const FillCentre& c : r.centres) {
    val o = val::object();
    o.set("patch", c.patch);
    o.set("normalSpreadDeg", c.normalSpreadDeg);
    o.set("normalSpreadOuterDeg", c.normalSpreadOuterDeg);
    o.set("fold", c.fold);
    o.set("curvatureNear", c.curvatureNear);
    o.set("curvatureRatio", c.curvatureRatio);
    o.set("ok", c.ok);
    centres.call<void>("push", o);
  }
  report.set("centres", centres);
  // The model's bodies (issue 36): closed or open, area, a closed one's volume.
  val out = val::array();
  for (const Body& b : bodies) {
    val o = val::object();
    val names = val::array();
    for (const std::string& n : b.patches) names.call<void>("push", n);
    o.set("patches", names);
    o.set("closed", b.closed);
    o.set("area", b.area);
    o.set("volume", b.volume);
    o.set("freeEdges", b.freeEdges);
    out.call<void>("push", o);
  }
  report.set("bodies", out);
  return report;
}

val reportFailure(const Error& e, bool crossingsChecked) {
  val report = val::object();
  report.set("crossingsChecked", crossingsChecked);
  val err = val::object();
  err.set("code", std::string(errorCodeName(e.code())));
  err.set("message", std::string(e.what()));
  report.set("ok", false);
  report.set("error", err);
  report.set("joins", val::array());
  report.set("seams", val::array());
  report.set("crossings", val::array());
  return report;
}

}  // namespace pdesurf::wasm
