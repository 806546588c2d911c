// The tabulation's shared work (surface/tabulation.cpp) gives what each term alone gives: the
// exponentials kept per (rate, shift) across terms (ExpOnGrid) and a general function's orders
// run as one program (evalManyUpTo), on every solved patch of every example.
#include <doctest.h>

#include <filesystem>
#include <set>

#include "basis/general_function.hpp"
#include "test_util.hpp"

using namespace pdesurf;
using namespace pdesurf::testing;

TEST_CASE("shared tabulation: kept exponentials and one program for every order equal the term-by-term values") {
  size_t pieces = 0, kept = 0, generals = 0;
  for (const auto& entry : std::filesystem::directory_iterator(examplePath(""))) {
    const std::string file = entry.path().filename().string();
    if (entry.path().extension() != ".json" || file == "index.json") continue;
    INFO(file);
    const Scene scene = parseScene(readText(entry.path().string()));
    const auto solved = solveScene(scene);
    std::vector<double> u;
    for (int i = 0; i <= 20; ++i) u.push_back(i / 20.0);
    for (const SolvedPatch& sp : solved) {
      ExpOnGrid exps(u.data(), int(u.size()));
      std::vector<double> alone(u.size() * 3), shared(u.size() * 3);
      std::set<std::pair<std::pair<double, double>, double>> rates;
      for (const auto& component : sp.surface.component)
        for (const SeparableTerm& t : component) {
          t.G.tabulate(u.data(), int(u.size()), 2, alone.data());
          t.G.tabulate(u.data(), int(u.size()), 2, shared.data(), nullptr, &exps);
          CHECK(alone == shared);
          for (const ExpPoly& p : t.G.pieces)
            if (p.rate != 0.0) ++pieces, rates.insert({{p.rate.real(), p.rate.imag()}, p.shift});
          if (t.g.family != Family::General) continue;
          ++generals;
          std::vector<double> v(u), a0(u.size()), a1(u.size()), a2(u.size()), b0(u.size()), b1(u.size()), b2(u.size());
          for (double& x : v) x = sp.surface.v0 + (sp.surface.v1 - sp.surface.v0) * x;
          t.g.general->evalMany(v.data(), v.size(), 0, a0.data());
          t.g.general->evalMany(v.data(), v.size(), 1, a1.data());
          t.g.general->evalMany(v.data(), v.size(), 2, a2.data());
          double* outs[3] = {b0.data(), b1.data(), b2.data()};
          t.g.general->evalManyUpTo(v.data(), v.size(), 2, outs);
          CHECK(a0 == b0);
          CHECK(a1 == b1);
          CHECK(a2 == b2);
        }
      kept += rates.size();
    }
  }
  MESSAGE("examples: " << pieces << " exponential pieces, " << kept << " distinct (rate, shift) per patch; " << generals << " general v-factors");
  CHECK(pieces > 0);
  CHECK(generals > 0);
  CHECK(kept < pieces);  // the sharing is real: terms do share their rates
}
