#include "report_values.hpp"

#include "analysis/report_json.hpp"
#include "js_values.hpp"

#include <string>

using emscripten::val;

namespace pdesurf::wasm {

val reportValue(const SceneReport& r, const std::vector<Body>& bodies, bool crossingsChecked) {
  val report = jsonValue(reportJson(r, bodies));  // the CLI's report, the same keys
  report.set("crossings_checked", crossingsChecked);
  return report;
}

val reportFailure(const Error& e, bool crossingsChecked) {
  val report = val::object();
  report.set("crossings_checked", crossingsChecked);
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
