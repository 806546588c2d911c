// pdesurf compare: every applicable method on one patch, measured against the closed form
// (or, where general terms have none, the reference solver).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <ostream>
#include <stdexcept>

#include "cli.hpp"
#include "methods/approximate.hpp"
#include "methods/measures.hpp"
#include "scene/scene.hpp"

namespace pdesurf::cli {

namespace {

// Median wall time of one solve, over samples that each batch enough solves to last ~5 ms.
double medianSolveMicroseconds(const PdeProblem& p, const Method& m) {
  using Clock = std::chrono::steady_clock;
  int batch = 1;
  for (;;) {
    const auto t0 = Clock::now();
    for (int i = 0; i < batch; ++i) solveWithMethod(p, m);
    if (std::chrono::duration<double>(Clock::now() - t0).count() > 5e-3 || batch >= 4096) break;
    batch *= 2;
  }
  std::vector<double> samples;
  for (int k = 0; k < 9; ++k) {
    const auto t0 = Clock::now();
    for (int i = 0; i < batch; ++i) solveWithMethod(p, m);
    samples.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count() / batch);
  }
  std::nth_element(samples.begin(), samples.begin() + 4, samples.end());
  return samples[4];
}

}  // namespace

int runCompare(const Options& o, std::ostream& out) {
  const Scene scene = parseScene(readFile(o.scenePath));
  const Patch* patch = o.patch.empty() ? scene.firstPde() : scene.find(o.patch);
  if (!patch || !patch->solvedAsPde())
    throw std::runtime_error(o.patch.empty() ? "the scene has no PDE patch" : "no PDE patch named '" + o.patch + "'");
  const int Iu = o.gridGiven ? o.nu : 100, Jv = o.gridGiven ? o.nv : 100;
  if (Iu < 2 || Jv < 2 || Iu > 2048 || Jv > 2048) throw std::runtime_error("--grid must be 2x2 .. 2048x2048 for compare");
  // The problem the scene solves: a chained end's or a fill's conditions derived from the
  // patches it depends on (issue 38 #10: the typed problem alone, a fill's empty, gave E = nan).
  const SolvedPatch solved = solvePatchIn(scene, *patch);
  const PdeProblem& problem = solved.pde();
  PdeProblem restored;
  const bool closed = restoreFamilies(problem, &restored);
  const MethodSolution ref = closed ? solveWithMethod(problem, parseMethod("closed")) : solveReference(problem);
  const std::string against = closed ? "closed" : "reference";

  nlohmann::json rows = nlohmann::json::array();
  for (const std::string& name : applicableMethods(problem)) {
    if (name == "auto") continue;
    const Method m = parseMethod(name);
    nlohmann::json row;
    row["method"] = name;
    try {
      const MethodSolution s = solveWithMethod(problem, m);
      row["E"] = relativeError(ref.surface, s.surface, Iu, Jv);
      row["bc_error"] = boundaryConditionError(problem, s.surface);
      row["residual"] = pdeResidual(problem, s.surface);
      row["solve_us"] = medianSolveMicroseconds(problem, m);
    } catch (const std::exception& e) {
      row["error"] = e.what();
    }
    rows.push_back(row);
  }
  if (o.json) {
    out << rows.dump(2) << "\n";
    return 0;
  }
  char line[200];
  std::snprintf(line, sizeof line, "patch '%s', E over %dx%d points against the %s solution\n", patch->name.c_str(), Iu, Jv, against.c_str());
  out << line;
  std::snprintf(line, sizeof line, "%-22s %14s %14s %14s %12s\n", "method", "E", "bc error", "PDE residual", "solve [us]");
  out << line;
  for (const auto& r : rows) {
    if (r.contains("error")) {
      std::snprintf(line, sizeof line, "%-22s %s\n", r["method"].get<std::string>().c_str(), r["error"].get<std::string>().c_str());
    } else {
      std::snprintf(line, sizeof line, "%-22s %14.6e %14.3e %14.3e %12.2f\n", r["method"].get<std::string>().c_str(), r["E"].get<double>(),
                    r["bc_error"].get<double>(), r["residual"].get<double>(), r["solve_us"].get<double>());
    }
    out << line;
  }
  return 0;
}

}  // namespace pdesurf::cli
