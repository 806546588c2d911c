// Issue 17, the certificate: a curve trimline that replaces t1 is reported as such (not as
// edge "t0"), and a join whose primary interval is not inside the primary's v_range (a
// Bézier border's meets.v_range, or a PDE blend's own v range) is a named error at parse,
// never a pass; a part of the border inside it (seed 002 Fig. 4) stays a join.
#include <doctest.h>

#include <nlohmann/json.hpp>

#include "analysis/join_certificate.hpp"
#include "common/errors.hpp"
#include "scene/scene.hpp"
#include "test_util.hpp"

using namespace pdesurf;
using namespace pdesurf::testing;
using json = nlohmann::json;

namespace {

json example(const std::string& id) { return json::parse(readText(examplePath(id + ".json"))); }

std::string errorOf(const json& j) {
  try {
    const Scene s = parseScene(j.dump());
    checkScene(s, solveScene(s), 0);
  } catch (const Error& e) {
    return std::string(errorCodeName(e.code())) + ": " + e.what();
  }
  return "";
}

// Seed 000 Fig. 4a by reference: the cylinder met along z = h0 + h1 sin(v/2), the curve
// replacing its border `replaces`; z runs up (t0 below) or down (t1 below) the cylinder so
// that the part kept is above the curve either way.
json fig4a(const std::string& replaces) {
  json j = example("you2004-fig4a");
  j["version"] = 3;
  json& blend = j["patches"][0];
  blend.erase("boundary");
  const bool down = replaces == "t1";
  blend["ends"] = {{"u0", {{"surface", "cylinder"},
                           {"at", {{"t", down ? "3 - h0 - h1*sin(0.5*v)" : "h0 + h1*sin(0.5*v)"}, {"replaces", replaces}}},
                           {"continuity", "tangency"},
                           {"power", "h0p + h1p*sin(0.5*v)"}}},
                   {"u1", {{"surface", "plane"}, {"at", "t0"}, {"continuity", "tangency"}, {"power", "Rp"}}}};
  for (json& p : j["patches"]) p.erase("meets");
  j["patches"][1]["z"] = down ? "3 - t" : "t";
  j["patches"][1]["t_range"] = json::array({0, 3});
  return j;
}

}  // namespace

TEST_CASE("certificate labels: a curve trimline is reported with the border it replaces") {
  for (const std::string replaces : {"t0", "t1"}) {
    CAPTURE(replaces);
    const Scene s = parseScene(fig4a(replaces).dump());
    const SceneReport r = checkScene(s, solveScene(s), 0);
    REQUIRE(r.joins.size() == 2);
    for (const JoinResult& j : r.joins) {
      CAPTURE(j.surface);
      CHECK(j.ok);
      CHECK(j.edge == (j.surface == "cylinder" ? "curve replacing " + replaces : std::string("t0")));
    }
  }
}

TEST_CASE("certificate: a join's interval outside the primary's v_range is a named error, a part inside it a join") {
  // Seed 002 Fig. 4: the side strips' borders run over v in [-1.5, 1.5]; the fill covers the
  // middle third (the rest meets the front and back strips): a join, and it passes.
  json j = example("wu2015-fig4");
  {
    const Scene s = parseScene(j.dump());
    const SceneReport r = checkScene(s, solveScene(s), 0);
    for (const JoinResult& k : r.joins) CHECK(k.ok);
  }
  // Past the end of the strip's border, in part or wholly: the primary would be evaluated where
  // it is not drawn and the join pass with the fill's border hanging free.
  for (const auto& range : {json::array({0.5, 2.5}), json::array({-2.0, -1.0}), json::array({2.0, 3.0})}) {
    CAPTURE(range.dump());
    json k = j;
    k["patches"][1]["meets"]["v_range"] = range;
    const std::string e = errorOf(k);
    CHECK(e.rfind("InvalidField: patches[1].meets.v_range: [", 0) == 0);
    CHECK(e.find("is not inside the v_range [-1.5, 1.5] of 'left'") != std::string::npos);
  }
  // A PDE blend sharing v with a primary whose v_range is shorter.
  json p = example("you2004-fig2a");
  p["patches"][1]["v_range"] = json::array({0, "pi"});
  CHECK(errorOf(p).find("patches[1].meets: the v_range [0, 6.28319] of pde patch 'blend' is not inside the v_range [0, 3.14159] of") !=
        std::string::npos);
}
