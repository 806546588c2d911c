// Version 3's rules between ends (scene/derived_ends.cpp, scene/trimline_checks.cpp): the
// result does not depend on the patches' order; both ends of one blend can meet one surface;
// a border replaced by a curve cannot be met; the trimline is checked over the surface's whole
// v_range; poles of tau and zeros of dS/dt between the samples are found; a kink of abs() in tau.
#include <doctest.h>

#include <nlohmann/json.hpp>

#include "analysis/join_certificate.hpp"
#include "common/errors.hpp"
#include "scene/scene.hpp"
#include "expr/parse.hpp"
#include "surface/mesh.hpp"
#include "test_util.hpp"

using namespace pdesurf;
using namespace pdesurf::testing;
using json = nlohmann::json;

namespace {

json surface(const std::string& name, const std::string& x, const std::string& y, const std::string& z, json t_range) {
  return {{"name", name}, {"kind", "surface"}, {"x", x}, {"y", y}, {"z", z}, {"t_range", t_range}, {"v_range", json::array({0, "2*pi"})}};
}

json blend(const std::string& name, json u0, json u1, json v_range = json::array({0, "2*pi"})) {
  return {{"name", name}, {"kind", "pde"}, {"v_range", v_range}, {"ends", {{"u0", u0}, {"u1", u1}}}};
}

json end(const std::string& surface, json at, const std::string& continuity = "tangency") {
  return {{"surface", surface}, {"at", at}, {"continuity", continuity}};
}

json sceneOf(json patches) { return {{"format", "pdesurf-scene"}, {"version", 3}, {"patches", patches}}; }

// A cylinder z = t in [0, 3] trimmed along z = 2 + 0.3 sin v (the curve replaces t1) by
// "upper", which rises to a ring at z = 3.5; "lower" leaves the cylinder's t0 (z = 0) down to a
// ring at z = -1. `upperFirst` puts the trimming blend first.
json twoBlends(bool upperFirst, const std::string& curve = "2 + 0.3*sin(v)", const char* lowerAt = "t0", bool withLower = true) {
  const json upper = blend("upper", end("cyl", {{"t", curve}, {"replaces", "t1"}}), end("top", "t0"));
  const json lower = blend("lower", end("cyl", lowerAt), end("bottom", "t0"));
  json patches = upperFirst ? json::array({upper, lower}) : json::array({lower, upper});
  patches.push_back(surface("cyl", "cos(v)", "sin(v)", "t", {0, 3}));
  patches.push_back(surface("top", "(1.5 + t)*cos(v)", "(1.5 + t)*sin(v)", "3.5", {0, 1}));
  patches.push_back(surface("bottom", "(1.5 + t)*cos(v)", "(1.5 + t)*sin(v)", "-1", {0, 1}));
  if (!withLower) patches.erase(upperFirst ? 1 : 0);
  return sceneOf(patches);
}

// "upper" alone (no other end on the cylinder).
json oneBlend(const std::string& curve) { return twoBlends(true, curve, "t0", false);
}

std::string errorOf(const json& j) {
  try {
    const Scene scene = parseScene(j.dump());
    checkScene(scene, solveScene(scene), 0);
  } catch (const Error& e) {
    return std::string(errorCodeName(e.code())) + ": " + e.what();
  }
  return "";
}

const SolvedPatch& named(const std::vector<SolvedPatch>& s, const std::string& name) {
  for (const SolvedPatch& p : s)
    if (p.patch->name == name) return p;
  throw std::runtime_error("no patch " + name);
}

}  // namespace

TEST_CASE("v3 rules: two blends on one surface give the same scene in either order, and it certifies") {
  const Scene a = parseScene(twoBlends(true).dump()), b = parseScene(twoBlends(false).dump());
  const auto sa = solveScene(a), sb = solveScene(b);
  double diff = 0.0;
  for (const char* name : {"upper", "lower", "cyl", "top", "bottom"}) {
    CAPTURE(name);
    const SeparableSurface &x = named(sa, name).surface, &y = named(sb, name).surface;
    for (int i = 0; i <= 24; ++i)
      for (int j = 0; j <= 24; ++j) {
        const double u = x.u0 + (x.u1 - x.u0) * i / 24.0, v = x.v0 + (x.v1 - x.v0) * j / 24.0;
        diff = std::max(diff, (evalPoint(x, u, v) - evalPoint(y, u, v)).norm());
      }
  }
  CHECK(diff == 0.0);
  for (const Scene* s : {&a, &b}) {
    const SceneReport r = checkScene(*s, s == &a ? sa : sb, 48);
    CHECK(r.joins.size() == 4);
    for (const JoinResult& j : r.joins) {
      CAPTURE(j.patch + ":" + j.end + " " + j.surface + ":" + j.edge);
      CAPTURE(j.g0);
      CHECK(j.ok);
    }
    CHECK(r.ok);
  }
  // The trimmed cylinder runs from the curve (t0) to its kept border z = 0 (t1).
  const Patch& cyl = *a.find("cyl");
  REQUIRE(cyl.meets.size() == 2);
  for (const Meets& m : cyl.meets) CHECK(m.atT1 == (m.patch == "lower"));
}

TEST_CASE("v3 rules: both ends of one blend on one surface (t0 and t1)") {
  // The upper half of a torus, t from the outer equator (t0) to the inner one (t1): the blend
  // leaves both downwards and closes the torus.
  const json s = sceneOf(json::array({blend("under", end("half", "t0"), end("half", "t1")),
                                      surface("half", "(2 + cos(pi*t))*cos(v)", "(2 + cos(pi*t))*sin(v)", "sin(pi*t)", {0, 1})}));
  CHECK(errorOf(s) == "");
  json same = s;
  same["patches"][0]["ends"]["u1"]["at"] = "t0";  // both on one border: no blend between them
  CHECK(errorOf(same) == "InvalidField: patches[0].ends.u1.at: meets t0 of 'half', as patches[0].ends.u0 does: the blend would start and end on the same curve");
  const Scene scene = parseScene(s.dump());
  const auto solved = solveScene(scene);
  const SceneReport r = checkScene(scene, solved, 48);
  REQUIRE(r.joins.size() == 2);
  CHECK(r.joins[0].end != r.joins[1].end);
  CHECK(r.joins[0].edge != r.joins[1].edge);
  for (const JoinResult& j : r.joins) CHECK(j.ok);
  CHECK(r.ok);
}

TEST_CASE("v3 rules: a border replaced by a curve cannot be met, in either order") {
  CHECK(errorOf(twoBlends(true, "2 + 0.3*sin(v)", "t1")) ==
        "InvalidField: patches[1].ends.u0.at: meets t1 of 'cyl', which patches[0].ends.u0 replaces by a curve");
  CHECK(errorOf(twoBlends(false, "2 + 0.3*sin(v)", "t1")) ==
        "InvalidField: patches[0].ends.u0.at: meets t1 of 'cyl', which patches[1].ends.u0 replaces by a curve");
  // Two curves on one surface: named, with the other end.
  json two = twoBlends(true);
  two["patches"][1]["ends"]["u0"]["at"] = {{"t", "1"}};
  CHECK(errorOf(two) == "InvalidField: patches[1].ends.u0.at: 'cyl' is already trimmed along a curve by patches[0].ends.u0; "
                        "a surface can be trimmed along one curve only");
}

TEST_CASE("v3 rules: the trimline is checked over the surface's whole v_range, where the trim applies") {
  json half = oneBlend("1 + 0.5*v");
  half["patches"][0]["v_range"] = json::array({0, "pi"});  // inside [0, 3] for v <= pi, not up to 2 pi
  half["patches"][0]["ends"]["u1"] = {{"surface", "top"}, {"at", "t0"}};
  const std::string e = errorOf(half);
  CHECK(e.find("InvalidField: patches[0].ends.u0.at: the trimline t = ") == 0);
  CHECK(e.find("is outside the t_range [0, 3] of 'cyl' (the trim applies over the surface's whole v_range)") != std::string::npos);
}

TEST_CASE("v3 rules: a pole of tau and a zero of dS/dt between the samples are found") {
  // 0.001/(v - 1.23456) leaves [0, 3] only within 7e-4 of the pole: between two of 129 samples.
  const std::string pole = errorOf(oneBlend("2 + 0.001/(v - 1.23456)"));
  CHECK(pole.find("InvalidField: patches[0].ends.u0.at: the trimline t = ") == 0);
  const size_t at = pole.find("at v = ");
  REQUIRE(at != std::string::npos);
  CHECK(std::abs(std::stod(pole.substr(at + 7)) - 1.23456) < 1e-3);
  // dS/dt = (0, 0, v - 1.23456) vanishes between samples on the iso-line t0.
  json flat = twoBlends(true);
  flat["patches"][2]["z"] = "t*(v - 1.23456)";
  flat["patches"][0]["ends"]["u0"]["at"] = "t1";
  flat["patches"][2]["t_range"] = json::array({0, 1});
  CHECK(errorOf(flat).find("InvalidField: patches[0].ends.u0.at: dS/dt of 'cyl' vanishes on the trimline at v = 1.23456") == 0);
}

TEST_CASE("v3 rules: a kink of abs() in tau is accepted (sign(0) = 0: the mean of the one-sided derivatives)") {
  // The kink at v = pi is a grid line of every even grid: abs's derivative there was 0/0.
  const Scene scene = parseScene(oneBlend("2 + 0.25*abs(v - pi)").dump());
  const auto solved = solveScene(scene);
  for (const SolvedPatch& p : solved) {
    CAPTURE(p.patch->name);
    for (int n : {64, 65, 128}) {
      const Mesh m = tessellate(p.surface, n, n, true);
      bool finite = true;
      for (float x : m.positions) finite = finite && std::isfinite(x);
      for (float x : m.normals) finite = finite && std::isfinite(x);
      CHECK(finite);
    }
  }
  CHECK(evaluate(*derivative(parseExpression("abs(v - 1)", {}, AllowedVariables{true, false}), ExprVar::V), std::array<double, 2>{1.0, 0.0}.data()) == 0.0);
  // And the joins keep their promise: the general method meets the kinked data exactly.
  const SceneReport r = checkScene(scene, solved, 0);
  CHECK(!r.joins.empty());
  for (const JoinResult& j : r.joins) {
    CAPTURE(j.g0);
    CAPTURE(j.g1Deg);
    CHECK(j.ok);
  }
}
