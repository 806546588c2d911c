// A fill's border along a surface's trimline curve t = τ(v) (issue 35, "every border a user
// has"): the surface is trimmed along it as for a blend's end, and the fill meets the curve.
#include <doctest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>

#include "analysis/interior_creases.hpp"
#include "analysis/join_certificate.hpp"
#include "scene/scene.hpp"
#include "test_util.hpp"

using namespace pdesurf;
using namespace pdesurf::testing;
using json = nlohmann::json;

namespace {

// Tubes along z in t, each a "surface" patch family users type: a cylinder, a cone, a band of a
// sphere (t a latitude), a wavy elliptic tube.
struct Tube {
  const char *x, *y, *z;
  double t0, t1;
};
const Tube kTubes[] = {
    {"cos(v)", "sin(v)", "t", 0, 2},
    {"(1 + 0.3*t)*cos(v)", "(1 + 0.3*t)*sin(v)", "t", 0, 2},
    {"cos(t)*cos(v)", "cos(t)*sin(v)", "sin(t)", -1, 1},
    {"1.3*(1 + 0.1*sin(3*v))*cos(v)", "0.8*sin(v)", "t + 0.1*cos(v)", 0, 2},
};

// The same surface as the scene's expressions, for an independent look at the trimline.
Eigen::Vector3d tubeAt(int kind, double t, double v) {
  switch (kind) {
    case 0: return {std::cos(v), std::sin(v), t};
    case 1: return {(1 + 0.3 * t) * std::cos(v), (1 + 0.3 * t) * std::sin(v), t};
    case 2: return {std::cos(t) * std::cos(v), std::cos(t) * std::sin(v), std::sin(t)};
    default: return {1.3 * (1 + 0.1 * std::sin(3 * v)) * std::cos(v), 0.8 * std::sin(v), t + 0.1 * std::cos(v)};
  }
}

const JoinResult* seamOf(const SceneReport& r, const std::string& patch) {
  for (const JoinResult& s : r.seams)
    if (s.patch == patch) return &s;
  return nullptr;
}

}  // namespace

TEST_CASE("fills along random trimline curves of every tube family, 1 to 3 borders, G1 and G2") {
  std::mt19937 rng(3501);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int trials = kTimeScale > 1 ? 6 : 16;
  for (int trial = 0; trial < trials; ++trial) {
    const int kind = trial % 4;
    const Tube& tube = kTubes[kind];
    const bool atTop = trial % 3 == 2;           // the curve replaces t1: a cap on top
    const int n = 1 + (trial / 2) % 3;            // the curve split into n ranges
    const bool g2 = trial % 2 == 1;
    const double span = tube.t1 - tube.t0, c0 = tube.t0 + span * (atTop ? 0.7 : 0.3);
    const double c1 = 0.12 * span * unit(rng), c2 = 0.05 * span * unit(rng), phase = 6.28 * unit(rng);
    char tau[160];
    std::snprintf(tau, sizeof tau, "%.17g + %.17g*sin(v + %.17g) + %.17g*cos(2*v)", c0, c1, phase, c2);
    CAPTURE(kind);
    CAPTURE(tau);
    CAPTURE(n);
    CAPTURE(g2);
    json borders = json::array();
    for (int k = 0; k < n; ++k)
      borders.push_back({{"patch", "tube"}, {"at", {{"t", tau}, {"replaces", atTop ? "t1" : "t0"}}}, {"range", {2 * M_PI * k / n, 2 * M_PI * (k + 1) / n}}});
    json fill = {{"name", "cap"}, {"kind", "fill"}, {"borders", borders}};
    if (g2) fill["continuity"] = "curvature";
    const json surface = {{"name", "tube"}, {"kind", "surface"}, {"t_range", {tube.t0, tube.t1}}, {"v_range", {0, "2*pi"}},
                          {"x", tube.x}, {"y", tube.y}, {"z", tube.z}};
    const json scene = {{"format", "pdesurf-scene"}, {"version", 4}, {"patches", json::array({surface, fill})}};
    const Scene parsed = parseScene(scene.dump());
    const auto solved = solveScene(parsed);
    const SceneReport r = checkScene(parsed, solved, 0);
    REQUIRE(r.joins.size() == static_cast<size_t>(n));
    for (const JoinResult& j : r.joins) {
      CHECK(j.edge == (atTop ? "curve replacing t1" : "curve replacing t0"));
      CHECK(j.level == (g2 ? 2 : 1));
      CHECK(j.g0 < 1e-12);
      CHECK(j.g1Deg < 1e-8);
      if (g2) CHECK(j.g2Rel < 1e-8);
      CHECK(j.ok);
    }
    const JoinResult* seam = seamOf(r, "cap");
    REQUIRE(seam);
    CHECK(seam->g0 < 1e-12);
    CHECK(seam->ok);
    REQUIRE(r.centres.size() == 1);
    CHECK(r.centres[0].ok);
    CHECK(r.ok);
    // Independently of the certificate: the fill's loop is the tube at t = τ(v), taken from
    // the formulas above, not from the scene's expressions (the loop's border k runs over the
    // curve's range k; with one border, v itself).
    const SeparableSurface& s = solvedNamed(solved, "cap").surface;
    const auto tauAt = [&](double v) { return c0 + c1 * std::sin(v + phase) + c2 * std::cos(2 * v); };
    if (n == 1)
      for (int i = 0; i < 24; ++i) {
        const double v = 2 * M_PI * i / 24;
        CHECK((evalPoint(s, 0.0, v) - tubeAt(kind, tauAt(v), v)).norm() < 1e-12);
      }
    // The trimmed tube keeps the side away from the cap: its drawn t = 0 is the curve, its t = 1
    // the border the curve does not replace.
    const SeparableSurface& t = solvedNamed(solved, "tube").surface;
    for (double v : {0.3, 2.0, 4.4}) {
      CHECK((evalPoint(t, 0.0, v) - tubeAt(kind, tauAt(v), v)).norm() < 1e-12);
      CHECK((evalPoint(t, 1.0, v) - tubeAt(kind, atTop ? tube.t0 : tube.t1, v)).norm() < 1e-12);
    }
    // No crease inside: the loop is smooth (its ranges meet on one curve of one surface). Next
    // to a wavy wall the fill turns by up to 14° per cell of 128² at u = 0.05, and the measure
    // there falls 5 to 40 times per halving (e.g. 0.75°, 0.078°, 0.016°, 0.0004° from 64² to
    // 512²): a fast smooth turn. A crease would stay as the grid is refined.
    const InteriorCreases coarse = measureCreases("cap", s), fine = measureCreases("cap", s, 256);
    CAPTURE(coarse.creaseDeg);
    CAPTURE(fine.creaseDeg);
    CHECK((fine.creaseDeg < kCreaseToleranceDeg || fine.creaseDeg < coarse.creaseDeg / 3));
  }
}

TEST_CASE("a fill's trimline curve: one curve per surface, shared with a blend's end, its borders by their own names") {
  const auto scene = [](const json& extra, const json& capAt) {
    json patches = {{{"name", "tube"}, {"kind", "surface"}, {"t_range", {0, 2}}, {"v_range", {0, "2*pi"}}, {"x", "cos(v)"}, {"y", "sin(v)"}, {"z", "t"}},
                    {{"name", "cap"}, {"kind", "fill"}, {"borders", {{{"patch", "tube"}, {"at", capAt}}}}}};
    for (const json& p : extra) patches.push_back(p);
    return json{{"format", "pdesurf-scene"}, {"version", 4}, {"patches", patches}}.dump();
  };
  const json curve = {{"t", "0.5 + 0.2*sin(v)"}};
  const json top = {{"name", "top"}, {"kind", "surface"}, {"t_range", {0, 1}}, {"v_range", {0, "2*pi"}}, {"x", "(1.5 + t)*cos(v)"}, {"y", "(1.5 + t)*sin(v)"}, {"z", "3"}};
  // A blend from the tube's other border t1 (its drawn edge 1 once trimmed) to a flange.
  const json blend = {{"name", "blend"}, {"kind", "pde"}, {"v_range", {0, "2*pi"}},
                      {"ends", {{"u0", {{"surface", "tube"}, {"at", "t1"}}}, {"u1", {{"surface", "top"}, {"at", "t0"}}}}}};
  {
    const Scene s = parseScene(scene({top, blend}, curve));
    const SceneReport r = checkScene(s, solveScene(s), 0);
    CHECK(r.ok);
    CHECK(r.joins.size() == 3);
  }
  // The same curve met by a blend's end and a fill over all of it: one trim, but three sheets
  // along the curve (the trimmed tube, the cap and the skirt) - refused by name.
  const json sameCurveBlend = {{"name", "skirt"}, {"kind", "pde"}, {"v_range", {0, "2*pi"}},
                               {"ends", {{"u0", {{"surface", "tube"}, {"at", curve}}}, {"u1", {{"surface", "top"}, {"at", "t0"}}}}}};
  CHECK(parseErrorOf(scene({top, sameCurveBlend}, curve)) ==
        "InvalidField: patches[3].ends.u0: the curve trimming 'tube' is already met by patches[1].borders[0] ('cap') over [0, 6.28319]: three sheets would meet along it");
  // A second, different curve on the same surface.
  const json otherCurveBlend = {{"name", "skirt"}, {"kind", "pde"}, {"v_range", {0, "2*pi"}},
                                {"ends", {{"u0", {{"surface", "tube"}, {"at", {{"t", "1.5"}}}}}, {"u1", {{"surface", "top"}, {"at", "t0"}}}}}};
  CHECK(parseErrorOf(scene({top, otherCurveBlend}, curve)) ==
        "InvalidField: patches[3].ends.u0.at: 'tube' is already trimmed along a curve by patches[1].borders[0]; a surface can be trimmed along one curve only");
  // A second fill on the border the curve replaces.
  const json second = {{"name", "cap2"}, {"kind", "fill"}, {"borders", {{{"patch", "tube"}, {"at", "t0"}}}}};
  CHECK(parseErrorOf(scene(json::array({second}), curve)) == "InvalidField: patches[2].borders[0].at: meets t0 of 'tube', which patches[1].borders[0] replaces by a curve");
  // The curve must stay inside the surface's t_range, over its whole v_range.
  CHECK(parseErrorOf(scene(json::array(), json{{"t", "0.5 + 2*sin(v)"}})).rfind("InvalidField: patches[1].borders[0].at: the trimline t = ", 0) == 0);
  CHECK(parseErrorOf(scene(json::array(), json{{"t", "0.5", "x"}})).find("patches[1].borders[0].at") != std::string::npos);
  CHECK(parseErrorOf(scene(json::array(), json{{"t", "0.5"}, {"replaces", "t2"}})) == "InvalidField: patches[1].borders[0].at.replaces: expected \"t0\" or \"t1\"");
  // A curve on a pde patch's end: no trimline there.
  const json other = {{"name", "cap3"}, {"kind", "fill"}, {"borders", {{{"patch", "blend"}, {"at", curve}}}}};
  CHECK(parseErrorOf(scene({top, blend, other}, "t0")) ==
        "InvalidField: patches[4].borders[0].at: 'blend' is a pde patch; a trimline curve is drawn on a \"surface\" patch (expressions in t and v)");
}

TEST_CASE("a fill on the far border of a surface a blend trims: glued to that border, labelled by its own name; the replaced one refused") {
  // Issue 38 #5: a cylinder trimmed by a blend along t = 0.5 + 0.1 sin v (replacing t1), a cap
  // on its t0. The cap must close the bottom circle (z = 0) and say "t0", not the trimmed
  // parametrisation's "t1"; a cap on the replaced t1 is refused.
  const auto scene = [](const char* capAt, bool capFirst) {
    const json tube = {{"name", "A"}, {"kind", "surface"}, {"t_range", {0, 2}}, {"v_range", {0, "2*pi"}}, {"x", "cos(v)"}, {"y", "sin(v)"}, {"z", "t"}};
    const json flange = {{"name", "B"}, {"kind", "surface"}, {"t_range", {0, 1}}, {"v_range", {0, "2*pi"}}, {"x", "(2 + t)*cos(v)"}, {"y", "(2 + t)*sin(v)"}, {"z", "1.5"}};
    const json blend = {{"name", "blend"}, {"kind", "pde"}, {"v_range", {0, "2*pi"}},
                        {"ends", {{"u0", {{"surface", "A"}, {"at", {{"t", "0.5 + 0.1*sin(v)"}, {"replaces", "t1"}}}}}, {"u1", {{"surface", "B"}, {"at", "t0"}}}}}};
    const json cap = {{"name", "cap"}, {"kind", "fill"}, {"borders", {{{"patch", "A"}, {"at", capAt}}}}};
    json patches = capFirst ? json::array({tube, flange, cap, blend}) : json::array({tube, flange, blend, cap});
    return json{{"format", "pdesurf-scene"}, {"version", 4}, {"patches", patches}}.dump();
  };
  for (bool capFirst : {false, true}) {
    CAPTURE(capFirst);
    const Scene s = parseScene(scene("t0", capFirst));
    const auto solved = solveScene(s);
    const SeparableSurface& cap = solvedNamed(solved, "cap").surface;
    for (double v = 0.1; v < 6.2; v += 0.5) {
      const Eigen::Vector3d x = evalPoint(cap, 0.0, v);
      CHECK(std::abs(x.z()) < 1e-12);                        // on the bottom circle
      CHECK(std::abs(std::hypot(x.x(), x.y()) - 1) < 1e-12);
    }
    const SceneReport r = checkScene(s, solved, 0);
    CHECK(r.ok);
    bool labelled = false;
    for (const JoinResult& j : r.joins)
      if (j.patch == "cap") labelled = j.surface == "A" && j.edge == "t0";
    CHECK(labelled);
    CHECK(parseErrorOf(scene("t1", capFirst)).find("meets t1 of 'A', which patches[") != std::string::npos);
  }
}
