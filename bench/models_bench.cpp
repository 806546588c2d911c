// Benchmark section (not a test): a model of many patches, seed 000 Fig. 8d's aeroplane
// (docs/chains-and-fills.md). The whole model's parse, solve and 64² drawing from cold; each
// patch's own solve and drawing; and the re-solve after one wing parameter with a SolveCache,
// which solves only the patches downstream of the wing (the page's module keeps the others'
// meshes too).
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>

#include "analysis/fill_centre.hpp"
#include "common/errors.hpp"
#include "methods/method.hpp"
#include "scene/chain_conditions.hpp"
#include "scene/scene.hpp"
#include "surface/mesh.hpp"

namespace pdesurf {

double benchMedianSeconds(const std::function<void()>& f);  // bench.cpp

// Each fill's whole solve as the page asks it (issue 35): its loop derived from the solved
// borders, the modal solve and the regularity check (what solveScene does for it when it is not
// cached), each on its own and all three from nothing; and its drawing at 64².
void benchFills(const std::string& dir, const char* file) {
  std::ifstream in(dir + "/" + file, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  const Scene scene = parseScene(ss.str());
  const auto solved = solveScene(scene);
  const SolvedLookup lookup = [&](const std::string& name) -> const SolvedPatch& {
    for (const SolvedPatch& sp : solved)
      if (sp.patch->name == name) return sp;
    throw Error(ErrorCode::Internal, "no patch " + name);
  };
  volatile size_t sink = 0;
  std::printf("\nfills of %s [us, median]\n%-12s %10s %10s %10s %10s %12s\n", file, "fill", "derive", "solve", "check", "total", "draw 64x64");
  for (const SolvedPatch& sp : solved) {
    if (!sp.patch->isFill()) continue;
    const Patch& fill = *sp.patch;
    const double derive = benchMedianSeconds([&] { sink = derivedProblem(fill, lookup)->component[0].left.size(); });
    const auto problem = derivedProblem(fill, lookup);
    const double solve = benchMedianSeconds([&] { sink = solveWithMethod(*problem, fill.method()).surface.component[0].size(); });
    const SeparableSurface surface = solveWithMethod(*problem, fill.method()).surface;
    const double check = benchMedianSeconds([&] { checkFillRegular(fill, surface), sink = 1; });
    // The whole path from nothing, as one: the parts above reuse what a first run compiled (a
    // general function's programs), the page's solve does not.
    const double total = benchMedianSeconds([&] {
      const auto fresh = derivedProblem(fill, lookup);
      const SeparableSurface s = solveWithMethod(*fresh, fill.method()).surface;
      checkFillRegular(fill, s);
      sink = s.component[0].size();
    });
    const double draw = benchMedianSeconds([&] { sink = tessellate(surface, 64, 64).vertexCount(); });
    std::printf("%-12s %10.1f %10.1f %10.1f %10.1f %12.1f\n", fill.name.c_str(), derive * 1e6, solve * 1e6, check * 1e6, total * 1e6, draw * 1e6);
  }
}

void benchModels(const std::string& dir) {
  std::ifstream in(dir + "/you2004-fig8d.json", std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  auto withWing = [&](double dx) {
    auto j = nlohmann::json::parse(text);
    j["parameters"]["wing_x"]["value"] = j["parameters"]["wing_x"]["value"].get<double>() + dx;
    return j.dump();
  };
  volatile size_t sink = 0;
  const Scene scene = parseScene(text);
  const auto solved = solveScene(scene);
  std::printf("\nthe aeroplane (you2004-fig8d, %zu patches) [us, median]\n%-12s %-8s %12s %14s\n", scene.patches.size(), "patch", "kind",
              "solve", "draw 64x64");
  double sumSolve = 0, sumDraw = 0;
  for (const SolvedPatch& sp : solved) {
    double solve = 0;
    if (sp.patch->solvedAsPde()) {
      const PdeProblem& p = sp.pde();
      solve = benchMedianSeconds([&] { sink = solveWithMethod(p, sp.patch->method()).surface.component[0].size(); });
    }
    const double draw = benchMedianSeconds([&] { sink = tessellate(sp.surface, 64, 64).vertexCount(); });
    sumSolve += solve, sumDraw += draw;
    std::printf("%-12s %-8s %12.1f %14.1f\n", sp.patch->name.c_str(), sp.patch->kindName.c_str(), solve * 1e6, draw * 1e6);
  }
  std::printf("%-21s %12.1f %14.1f   (the patches one by one)\n", "sum", sumSolve * 1e6, sumDraw * 1e6);
  const double whole = benchMedianSeconds([&] {
    const Scene s = parseScene(text);
    for (const SolvedPatch& sp : solveScene(s)) sink = tessellate(sp.surface, 64, 64).vertexCount();
  });
  // One wing parameter, back and forth: each solve parses the scene, re-derives everything and
  // solves again only what the wing reaches (rootL, rootR, tipL, tipR); those are drawn again.
  SolveCache cache;
  const std::string a = withWing(0.0), b = withWing(0.05);
  solveScene(parseScene(a), &cache);
  bool flip = false;
  size_t resolved = 0;
  const double wing = benchMedianSeconds([&] {
    flip = !flip;
    const Scene s = parseScene(flip ? b : a);
    resolved = 0;
    for (const SolvedPatch& sp : solveScene(s, &cache))
      if (!sp.reused && sp.patch->solvedAsPde()) ++resolved, sink = tessellate(sp.surface, 64, 64).vertexCount();
  });
  std::printf("whole model, parse + solve + draw 64x64, cold: %.1f us\n", whole * 1e6);
  benchFills(dir, "you2004-fig8c.json");
  benchFills(dir, "you2004-fig8d.json");
  std::printf("after one wing parameter (cached; %zu patches re-solved and re-drawn): %.1f us, %.2f of the cold model\n", resolved, wing * 1e6,
              wing / whole);
}

}  // namespace pdesurf
