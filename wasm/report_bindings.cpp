// The join report of the module's last solve, part by part (docs/wasm-api.md): the page's
// worker posts the mesh first and certifies after, in slices it can stop between when the
// next edit arrives. Parts whose surfaces did not change are kept from the previous report
// (analysis/report_session.hpp).
//   reportBegin({crossings}) -> {ok, parts}                  starts the report of the last solve
//   reportStep(budgetMs)     -> {ok, done, left, measured, kept, report?}
//     measures parts until the budget is spent (at least one); with done, the whole report.
#include <emscripten/bind.h>
#include <emscripten/emscripten.h>
#include <emscripten/val.h>

#include "analysis/report_session.hpp"
#include "js_values.hpp"
#include "kept_solve.hpp"
#include "report_values.hpp"

using emscripten::val;
using namespace pdesurf;

namespace pdesurf::wasm {
namespace {

KeptSolve kept;

struct Report {
  ReportSession session;
  KeptSolve of;  // the solve being reported (held: the session points into it)
  bool crossings = false;
  bool started = false;
};

Report& current() {
  static Report r;
  return r;
}

val reportBegin(val options) {
  return guarded("a smaller scene", [&]() -> val {
    Report& r = current();
    if (!kept.solved) throw Error(ErrorCode::InvalidField, "reportBegin: no solve to report (solve first)");
    const bool isObject = !options.isUndefined() && !options.isNull() && options.typeOf().as<std::string>() == "object";
    r.crossings = isObject && options["crossings"].typeOf().as<std::string>() == "boolean" && options["crossings"].as<bool>();
    r.of = kept;
    r.session.begin(*r.of.scene, *r.of.solved, r.crossings ? 48 : 0);
    r.started = true;
    val out = val::object();
    out.set("ok", true);
    out.set("parts", double(r.session.partsLeft()));
    out.set("generation", double(r.of.generation));
    return out;
  });
}

val reportStep(val budgetArg) {
  Report& r = current();
  if (!r.started) return failure("InvalidField", "reportStep: no report begun (reportBegin first)");
  const double budget = budgetArg.typeOf().as<std::string>() == "number" ? budgetArg.as<double>() : 0.0;
  try {
    const double t0 = emscripten_get_now();
    bool done = r.session.step();
    while (!done && emscripten_get_now() - t0 < budget) done = r.session.step();
    val out = val::object();
    out.set("ok", true);
    out.set("done", done);
    out.set("left", double(r.session.partsLeft()));
    out.set("measured", double(r.session.partsMeasured()));
    out.set("kept", double(r.session.partsKept()));
    if (done) out.set("report", reportValue(r.session.report(), r.session.bodies(), r.crossings));
    return out;
  } catch (const Error& e) {
    // The same as the all-at-once report: a scene whose declared join is wrong still draws.
    r.started = false;
    val out = val::object();
    out.set("ok", true);
    out.set("done", true);
    out.set("report", reportFailure(e, r.crossings));
    return out;
  } catch (const std::bad_alloc&) {
    r.started = false;
    return failure("Internal", "out of memory: a smaller scene");
  } catch (const std::exception& e) {
    r.started = false;
    return failure("Internal", e.what());
  }
}

}  // namespace

void keepSolve(std::shared_ptr<const Scene> scene, std::shared_ptr<const std::vector<SolvedPatch>> solved) {
  kept.scene = std::move(scene);
  kept.solved = std::move(solved);
  ++kept.generation;
}

}  // namespace pdesurf::wasm

EMSCRIPTEN_BINDINGS(pdesurf_report) {
  emscripten::function("reportBegin", &pdesurf::wasm::reportBegin);
  emscripten::function("reportStep", &pdesurf::wasm::reportStep);
}
