// Chained ends (scene version 4, scene/chain_conditions.hpp): a pde patch's end continues
// another pde patch's end or a Bézier border exactly, consecutive patches meet G1 or G2 (the
// certificate judges it), patches solve in dependency order, a cycle is refused naming its
// patches, and a cache re-solves only the patches whose derived problem changed.
#include <doctest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <random>

#include "analysis/join_certificate.hpp"
#include "common/limits.hpp"
#include "scene/chain_conditions.hpp"
#include "scene/scene.hpp"
#include "test_util.hpp"

using namespace pdesurf;
using namespace pdesurf::testing;
using json = nlohmann::json;

namespace {

std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "(%.17g)", x);
  return buf;
}

// A tube `a` (typed at both ends) and `b` continuing a's u1 with `continuity`; b's far end is
// typed. Order 6 when curvature is asked (a then carries X_uu too).
json chainScene(double r0, double r1, double r2, double tilt, double power, const std::string& continuity, int sourceOrder) {
  const bool g2 = continuity == "curvature";
  json a = {{"name", "a"}, {"kind", "pde"}, {"v_range", {0, "2*pi"}}};
  a["operator"] = sourceOrder == 2 ? json{{"order", 2}, {"s", 1}, {"t", 1}} : sourceOrder == 4 ? json{{"order", 4}, {"b", 1}, {"c", 2}, {"d", 1}} : json{{"order", 6}, {"a", 1}};
  auto cond = [&](const std::string& x0, const std::string& x1, const std::string& d) {
    json u0 = json::array({x0}), u1 = json::array({x1});
    for (int i = 1; i < sourceOrder / 2; ++i) u0.push_back(i == 1 ? d : "0"), u1.push_back(i == 1 ? d : "0");
    return json{{"u0", u0}, {"u1", u1}};
  };
  a["boundary"] = {{"x", cond(num(r0) + "*cos(v)", num(r1) + "*cos(v)", "0")},
                   {"y", cond(num(r0) + "*sin(v)", num(r1) + "*sin(v) + " + num(tilt) + "*cos(2*v)", "0")},
                   {"z", cond("0", "1", "1")}};
  json b = {{"name", "b"}, {"kind", "pde"}, {"v_range", {0, "2*pi"}}};
  b["ends"] = {{"u0", {{"patch", "a"}, {"at", "u1"}, {"continuity", continuity}, {"power", power}}}};
  const int n = g2 ? 3 : continuity == "tangency" ? 2 : 1;
  auto far = [&](const std::string& x) {
    json l = json::array({x});
    for (int i = 1; i < n; ++i) l.push_back(i == 1 ? "0.5" : "0");
    return l;
  };
  b["boundary"] = {{"x", {{"u1", far(num(r2) + "*cos(v)")}}}, {"y", {{"u1", far(num(r2) + "*sin(v)")}}}, {"z", {{"u1", far("2.2")}}}};
  return {{"format", "pdesurf-scene"}, {"version", 4}, {"patches", {b, a}}};  // b first: the order is the graph's
}

}  // namespace

TEST_CASE("a chained end continues the patch it names exactly, G1 and G2, over random tubes") {
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> r(0.6, 1.6), tilt(-0.2, 0.2), power(0.4, 2.0);
  for (int trial = 0; trial < 12; ++trial) {
    const std::string continuity = trial % 3 == 2 ? "curvature" : "tangency";
    // Tangency from a 2nd-order source: its X_u comes from its solution, not its data.
    const int order = continuity == "curvature" ? 6 : trial % 3 == 1 ? 2 : 4;
    const double p = power(rng);
    const Scene scene = parseScene(chainScene(r(rng), r(rng), r(rng), tilt(rng), p, continuity, order).dump());
    CHECK(scene.patches[scene.solveOrder[0]].name == "a");
    const auto solved = solveScene(scene);
    const SceneReport report = checkScene(scene, solved, 0);
    REQUIRE(report.joins.size() == 1);
    CHECK(report.joins[0].level == (continuity == "curvature" ? 2 : 1));
    CHECK(report.joins[0].ok);
    const SeparableSurface &A = solvedNamed(solved, "a").surface, &B = solvedNamed(solved, "b").surface;
    for (double v = 0; v < 6.28; v += 0.37) {
      CHECK((evalPoint(B, 0, v) - evalPoint(A, 1, v)).norm() < 1e-12);
      CHECK((evalPoint(B, 0, v, 1) - p * evalPoint(A, 1, v, 1)).norm() < 1e-11);
      if (continuity == "curvature") CHECK((evalPoint(B, 0, v, 2) - p * p * evalPoint(A, 1, v, 2)).norm() < 1e-9);
    }
  }
}

TEST_CASE("a chained end on a Bézier border meets it G1") {
  // A thin-plate Bézier patch (both outer rings fixed) and a pde patch continuing its u1 border.
  json net = json::array();
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j) net.push_back({j * 0.25, i * 0.25, 0.3 * std::sin(i * 0.7) * std::cos(j * 0.9)});
  json scene = {{"format", "pdesurf-scene"}, {"version", 4}};
  json bez = {{"name", "plate"}, {"kind", "bezier"}, {"energy", "thin-plate"}, {"degree", {4, 4}}, {"control_net", net}, {"lambda", 0}, {"gamma", 0}};
  json pde = {{"name", "ext"}, {"kind", "pde"}, {"v_range", {0, 1}}};
  pde["ends"] = {{"u0", {{"patch", "plate"}, {"at", "u1"}, {"continuity", "tangency"}}}};
  pde["boundary"] = {{"x", {{"u1", {"v", 0}}}}, {"y", {{"u1", {2, 1}}}}, {"z", {{"u1", {0.2, 0}}}}};
  scene["patches"] = {pde, bez};
  const Scene s = parseScene(scene.dump());
  const auto solved = solveScene(s);
  const SceneReport r = checkScene(s, solved, 0);
  REQUIRE(r.joins.size() == 1);
  CHECK(r.joins[0].surface == "plate");
  CHECK(r.joins[0].edge == "u1");
  CHECK(r.joins[0].g0 < 1e-12);
  CHECK(r.joins[0].g1Deg < 1e-8);
  CHECK(r.joins[0].ok);
}

TEST_CASE("references that cannot be solved are named errors") {
  json good = chainScene(1, 1.2, 1.1, 0.1, 1, "tangency", 4);
  SUBCASE("a cycle names its patches") {
    json s = good;
    s["patches"][1].erase("boundary");
    s["patches"][1]["ends"] = {{"u0", {{"patch", "b"}, {"at", "u1"}}}, {"u1", {{"patch", "b"}, {"at", "u0"}}}};
    s["patches"][0]["boundary"]["x"]["u1"] = {"cos(v)", 0};
    const std::string e = parseErrorOf(s.dump());
    CHECK(e.find("a cycle of references") != std::string::npos);
    CHECK(e.find("'a'") != std::string::npos);
    CHECK(e.find("'b'") != std::string::npos);
  }
  SUBCASE("itself") {
    json s = good;
    s["patches"][0]["ends"]["u0"]["patch"] = "b";
    CHECK(parseErrorOf(s.dump()).find("its own border") != std::string::npos);
  }
  SUBCASE("unknown patch, wrong edge, a surface, another v-range, an old version") {
    json s = good;
    s["patches"][0]["ends"]["u0"]["patch"] = "zz";
    CHECK(parseErrorOf(s.dump()).find("UnknownName: patches[0].ends.u0.patch: no patch named 'zz'") == 0);
    s = good;
    s["patches"][0]["ends"]["u0"]["at"] = "v0";
    CHECK(parseErrorOf(s.dump()).find("its ends are u0 and u1") != std::string::npos);
    s = good;
    s["patches"][1]["v_range"] = {0, 3};
    CHECK(parseErrorOf(s.dump()).find("shares v with the patch it continues") != std::string::npos);
    s = good;
    s["version"] = 3;
    CHECK(parseErrorOf(s.dump()).find("needs scene version 4") != std::string::npos);
    s = good;
    s["patches"][0]["ends"]["u0"]["power"] = 0;
    CHECK(parseErrorOf(s.dump()).find("power: must be positive") != std::string::npos);
  }
}

TEST_CASE("a cache re-solves only the patches downstream of an edit") {
  SolveCache cache;
  const Scene s0 = parseScene(chainScene(1, 1.2, 1.1, 0.1, 1, "tangency", 4).dump());
  const auto first = solveScene(s0, &cache);
  CHECK(!solvedNamed(first, "a").reused);
  const auto again = solveScene(s0, &cache);
  CHECK(solvedNamed(again, "a").reused);
  CHECK(solvedNamed(again, "b").reused);
  // b's far end only: a is reused, b is solved again.
  const Scene s1 = parseScene(chainScene(1, 1.2, 1.3, 0.1, 1, "tangency", 4).dump());
  const auto edited = solveScene(s1, &cache);
  CHECK(solvedNamed(edited, "a").reused);
  CHECK(!solvedNamed(edited, "b").reused);
  // a's far end: both again (b continues it).
  const Scene s2 = parseScene(chainScene(1, 1.25, 1.3, 0.1, 1, "tangency", 4).dump());
  const auto upstream = solveScene(s2, &cache);
  CHECK(!solvedNamed(upstream, "a").reused);
  CHECK(!solvedNamed(upstream, "b").reused);
  // The reused surfaces are the ones solved: the same figures as without the cache.
  const auto fresh = solveScene(s2);
  CHECK((evalPoint(solvedNamed(upstream, "b").surface, 0.4, 1.1) - evalPoint(solvedNamed(fresh, "b").surface, 0.4, 1.1)).norm() == 0);
}

TEST_CASE("the conditions derived in one solve are bounded summed over its patches, counted while building") {
  // Issue 38 #1: each chained patch was bounded alone, so a long chain's derivations summed
  // without limit. The aeroplane, the largest example, derives 5 310 nodes in all.
  const Scene scene = parseScene(readText(examplePath("bottle-solid.json")));
  const auto solved = solveScene(scene);
  const SolvedLookup lookup = [&](const std::string& name) -> const SolvedPatch& { return solvedNamed(solved, name); };
  const Patch& cap = *scene.find("cap");
  size_t used = 0;
  derivedProblem(cap, lookup, &used);
  CHECK(used > 0);
  CHECK(used < limits::kDerivedNodes);
  // The same derivation with the rest of the scene's budget nearly spent: refused at the limit.
  size_t spent = limits::kSceneDerivedNodes - used / 2;
  CHECK_THROWS_WITH_AS(derivedProblem(cap, lookup, &spent), doctest::Contains("summed over the scene"), Error);
  spent = limits::kSceneDerivedNodes - used;
  CHECK_NOTHROW(derivedProblem(cap, lookup, &spent));
  CHECK(spent == limits::kSceneDerivedNodes);
}
