// A typed surface is split into separable terms T(t)·g(v) and a pointwise rest
// (scene/expression_fields.cpp). Parts the split gives up on but that are still a product of a
// t-part made of families and any function of v (a wing's profile) become separable terms
// with a general g: drawn by tabulating g once per grid line. Random surfaces of such parts,
// of families and of parts that do not separate: the drawn surface is the typed expression.
#include <doctest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>
#include <string>

#include "expr/expr.hpp"
#include "scene/scene.hpp"
#include "surface/separable_surface.hpp"

using namespace pdesurf;

namespace {

std::string num(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", x);
  return std::string("(") + b + ")";
}

}  // namespace

TEST_CASE("typed surfaces: parts separable over v with a general profile are drawn as the expression says") {
  std::mt19937 rng(7121);
  std::uniform_real_distribution<double> c(-1.5, 1.5), at(0, 1);
  std::uniform_int_distribution<int> pick(0, 4);
  int separated = 0, checked = 0;
  for (int trial = 0; trial < 40; ++trial) {
    // A profile the split gives up on (a high power of a trig sum), times family parts of t.
    const std::string profile = "(cos(v/4) - sin(v/4))*(1 - (cos(v/4) - sin(v/4))^2)*(2.9 - 2.1*(cos(v/4) - sin(v/4))^2 + 3.3*(cos(v/4) - sin(v/4))^4 - 2*(cos(v/4) - sin(v/4))^6)";
    std::string xyz[3];
    for (std::string& e : xyz) {
      e = num(c(rng)) + "*t";
      for (int k = 0; k < 3; ++k) {
        switch (pick(rng)) {
          case 0: e += " - " + num(c(rng)) + "*(1 - " + num(c(rng)) + "*t)*" + profile; break;  // separable over v
          case 1: e += " + " + num(c(rng)) + "*t^2*" + profile; break;                         // separable over v
          case 2: e += " + " + num(c(rng)) + "*cos(v)*(1 + t)"; break;                          // families
          case 3: e += " + " + num(c(rng)) + "*sin(t*v)"; break;                                // not separable
          default: e += " + " + num(c(rng)) + "*exp(t)*sqrt(2 + sin(v))"; break;               // separable over v
        }
      }
    }
    nlohmann::json scene = {{"format", "pdesurf-scene"}, {"version", 2}, {"title", "t"}};
    scene["patches"] = nlohmann::json::array({{{"name", "s"}, {"kind", "surface"}, {"t_range", {0, 1}}, {"v_range", {0, 2 * M_PI}},
                                               {"x", xyz[0]}, {"y", xyz[1]}, {"z", xyz[2]}}});
    CAPTURE(scene.dump());
    const Scene parsed = parseScene(scene.dump());
    const auto solved = solveScene(parsed);
    const SeparableSurface& s = solved.front().surface;
    const PrimarySurface& p = parsed.patches.front().primary();
    for (int k = 0; k < 3; ++k) {
      for (const SeparableTerm& t : s.component[k]) separated += t.g.isGeneral();
      if (xyz[k].find("sin(t*v)") == std::string::npos) CHECK(!s.pointwise[k]);  // all of it separable
      for (int q = 0; q < 12; ++q) {
        const double t = at(rng), v = 2 * M_PI * at(rng);
        const double vars[2] = {v, t};
        const double want = evaluate(*p.full[k], vars), got = evalPoint(s, t, v)[k];
        CHECK(std::abs(got - want) <= 1e-12 * std::max(1.0, std::abs(want)));
        ++checked;
      }
    }
  }
  CHECK(separated > 0);
  MESSAGE(checked << " points, " << separated << " general profile terms");
}
