// The join certificate and the crossing test can fail: a tilted surface breaks G1 by a known
// angle, a surface laid back over the blend is a fold, a plane cut through a blend is a
// crossing, a join to the wrong edge is a named error; curvature matches closed forms.
#include <doctest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "analysis/join_certificate.hpp"
#include "bezier/bezier_solver.hpp"
#include "common/errors.hpp"
#include "surface/mesh.hpp"
#include "test_util.hpp"

using namespace pdesurf;
using namespace pdesurf::testing;

namespace {

nlohmann::json fig2a() { return nlohmann::json::parse(readText(examplePath("you2004-fig2a.json"))); }

SceneReport check(const nlohmann::json& j, int grid = 64) {
  const Scene scene = parseScene(j.dump());
  return checkScene(scene, solveScene(scene), grid);
}

const JoinResult& joinOf(const SceneReport& r, const std::string& surface) {
  for (const JoinResult& j : r.joins)
    if (j.surface == surface) return j;
  throw std::runtime_error("no join with " + surface);
}

}  // namespace

TEST_CASE("certificate: the cone-plane blend keeps G1 at both joins, nothing crosses") {
  const SceneReport r = check(fig2a());
  REQUIRE(r.joins.size() == 2);
  for (const JoinResult& j : r.joins) {
    CAPTURE(j.surface);
    CHECK(j.level == 1);
    CHECK(j.g0 < 1e-14);
    CHECK(j.g1Deg < 1e-10);
    CHECK(!j.fold);
    CHECK(j.degenerate == 0);
    CHECK(j.ok);
  }
  CHECK(r.crossings.empty());
  CHECK(r.ok);
}

TEST_CASE("certificate: a plane tilted at the trimline breaks G1 by its tilt angle") {
  auto j = fig2a();
  j["patches"][1]["z"] = "0.3*t";  // the plane's t-direction (0.5 radial, 0.3 up) against the blend's horizontal one
  const SceneReport r = check(j);
  const JoinResult& plane = joinOf(r, "plane");
  CHECK(plane.g0 < 1e-14);
  CHECK(plane.g1Deg == doctest::Approx(std::atan2(0.3, 0.5) * 180 / M_PI).epsilon(1e-9));
  CHECK(!plane.fold);
  CHECK(!plane.ok);
}

TEST_CASE("certificate: a plane laid back over the blend is a fold, whatever its G1 figure") {
  auto j = fig2a();
  j["patches"][1]["x"] = "r0*cos(v) + t*r0p*cos(v)";  // extends inwards, under the blend
  j["patches"][1]["y"] = "r0*sin(v) + t*r0p*sin(v)";
  const SceneReport r = check(j, 0);
  const JoinResult& plane = joinOf(r, "plane");
  CHECK(plane.g1Deg < 1e-10);  // the same tangent plane...
  CHECK(plane.fold);           // ... but both leave the circle inwards
  CHECK(!plane.ok);
  CHECK(joinOf(r, "cone").ok);
}

TEST_CASE("certificate: a plane cut through the blend is a crossing, reported where it is") {
  auto j = fig2a();
  j["patches"].push_back({{"name", "cutter"}, {"kind", "surface"}, {"t_range", {-3, 3}}, {"v_range", {-3, 3}}, {"x", "t"}, {"y", "v"}, {"z", "1"}});
  const SceneReport r = check(j);
  REQUIRE(r.crossings.size() == 1);
  const Crossing& c = r.crossings[0];
  CHECK(c.patch == "blend");
  CHECK(c.other == "cutter");
  CHECK(c.v[0] < 0.2);
  CHECK(c.v[1] > 2 * M_PI - 0.2);
  // The blend reaches z = 1 where its height profile crosses 1 (the same u at every v).
  const Scene scene = parseScene(j.dump());
  const SeparableSurface s = solvePatch(*scene.firstPde()).surface;
  double lo = 0, hi = 1;
  for (int it = 0; it < 60; ++it) (evalPoint(s, 0.5 * (lo + hi), 0.0)(2) < 1 ? lo : hi) = 0.5 * (lo + hi);
  CHECK(c.u[0] <= lo + 1e-12);
  CHECK(c.u[1] >= lo - 1e-12);
  CHECK(c.u[1] - c.u[0] < 0.1);
  CHECK(!r.ok);
}

TEST_CASE("crossings: a patch lying on another is a crossing; many on one another are bounded before the work") {
  // Issue 38 re-attack: 64 coincident Bezier squares were "0 crossings: ok" after 7.9 s (their
  // triangles share corners, which the test skips as touching), and grew with the pairs.
  const auto squares = [](int count) {
    nlohmann::json patches = nlohmann::json::array();
    for (int k = 0; k < count; ++k) {
      nlohmann::json net = nlohmann::json::array();
      for (int i = 0; i <= 3; ++i)
        for (int j = 0; j <= 3; ++j) net.push_back({i / 3.0, j / 3.0, 0.0});
      patches.push_back({{"name", "p" + std::to_string(k)}, {"kind", "bezier"}, {"energy", "membrane"}, {"degree", {3, 3}}, {"control_net", net}});
    }
    return nlohmann::json{{"format", "pdesurf-scene"}, {"version", 4}, {"patches", patches}};
  };
  {
    const SceneReport r = check(squares(2));
    REQUIRE(r.crossings.size() == 1);
    CHECK(r.crossings[0].patch == "p0");
    CHECK(r.crossings[0].other == "p1");
    CHECK(r.crossings[0].triangles > 100);
    CHECK(!r.ok);
  }
  // 64 on one another: the mesh is coarsened before any pair is compared, each pair still found.
  const SceneReport many = check(squares(64));
  CHECK(many.crossings.size() == 64 * 63 / 2);
  // 63 tiny squares on one another under one large one: every triangle in one cell of the hash
  // even at the coarsest mesh - refused, naming two of them, before a pair is compared.
  {
    nlohmann::json j = squares(64);
    for (auto& p : j["patches"])
      for (auto& x : p["control_net"]) x = {x[0].get<double>() * 1e-3, x[1].get<double>() * 1e-3, 0.0};
    for (auto& x : j["patches"][63]["control_net"]) x = {x[0].get<double>() * 1e7, x[1].get<double>() * 1e7, 5.0};
    const Scene scene = parseScene(j.dump());
    const auto solved = solveScene(scene);
    std::string error;
    try {
      checkScene(scene, solved, 64);
    } catch (const Error& e) {
      error = std::string(errorCodeName(e.code())) + ": " + e.what();
    }
    CHECK(error.rfind("TooLarge: the crossing test would compare ", 0) == 0);
    CHECK(error.find("on a 16x16 mesh per patch") != std::string::npos);
    CHECK(error.find("patches lie on one another ('p0' and 'p1')") != std::string::npos);
  }
  // One square alone, and the aeroplane at the largest grid (its mesh capped by the scene's
  // triangles): nothing crosses.
  CHECK(check(squares(1)).crossings.empty());
  const Scene plane = parseScene(readText(examplePath("you2004-fig8d.json")));
  CHECK(findCrossings(solveScene(plane), 10.0, 1181).empty());
}

TEST_CASE("certificate: a join to the wrong edge or a missing border is a named error") {
  auto j = fig2a();
  j["patches"][1]["meets"]["at"] = "t1";  // the plane's outer circle is not the blend's border
  const Scene scene = parseScene(j.dump());
  try {
    checkScene(scene, solveScene(scene));
    FAIL("expected an error");
  } catch (const Error& e) {
    CHECK(e.code() == ErrorCode::InvalidField);
    CHECK(std::string(e.what()).find("patches[1].meets") != std::string::npos);
    CHECK(std::string(e.what()).find("is not the border u0 of 'blend'") != std::string::npos);
  }
  auto k = fig2a();
  k["patches"][1]["meets"]["end"] = "v0";  // a PDE patch has only u-ends
  CHECK_THROWS_WITH_AS(parseScene(k.dump()), doctest::Contains("has ends u0 and u1 only"), Error);
  k["patches"][1]["meets"]["end"] = "w1";
  CHECK_THROWS_AS(parseScene(k.dump()), Error);
}

TEST_CASE("certificate: seed 003's C2 blend promises and keeps G2; a wrong curvature condition breaks it") {
  const SceneReport r = check(nlohmann::json::parse(readText(examplePath("zhang-c2-ex1.json"))), 0);
  for (const JoinResult& j : r.joins) {
    CAPTURE(j.surface);
    CHECK(j.level == 2);
    CHECK(j.g2Rel < 1e-9);
    CHECK(j.ok);
  }
}

TEST_CASE("curvature: a sphere has K = 1/R² and |H| = 1/R everywhere, finite at its poles") {
  auto j = nlohmann::json::parse(readText(examplePath("you2004-fig6.json")));
  j["patches"][2]["t_range"] = {0, "pi"};  // the whole sphere, both poles
  const Scene scene = parseScene(j.dump());
  const auto solved = solveScene(scene);
  const double R = scene.parameters.empty() ? 1.0 : [&] {
    for (const Parameter& p : scene.parameters)
      if (p.name == "R") return p.value;
    return 1.0;
  }();
  const Mesh m = tessellate(solved[2].surface, 24, 32, true);
  REQUIRE(m.meanCurvature.size() == m.vertexCount());
  int regular = 0;
  for (size_t k = 0; k < m.vertexCount(); ++k) {
    REQUIRE(std::isfinite(m.meanCurvature[k]));
    REQUIRE(std::isfinite(m.gaussCurvature[k]));
    const size_t i = k % 25;
    if (i == 0 || i == 24) continue;  // the poles: degenerate, reported as 0
    ++regular;
    CHECK(m.gaussCurvature[k] == doctest::Approx(1 / (R * R)).epsilon(1e-5));
    CHECK(std::abs(m.meanCurvature[k]) == doctest::Approx(1 / R).epsilon(1e-5));
  }
  CHECK(m.degenerateVertices == 2 * 33);
  CHECK(regular == 23 * 33);
}

TEST_CASE("curvature: a Bézier paraboloid z = x² + y² from its Bernstein second derivatives") {
  // Degree 2 net of z = x² + y² over [-1, 1]²: x = 2u - 1, y = 2v - 1.
  ControlNet net(9);
  const double xs[3] = {-1, 0, 1}, zc[3][3] = {{2, 0, 2}, {0, -2, 0}, {2, 0, 2}};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) net[i * 3 + k] = {xs[i], xs[k], zc[i][k]};
  // z = x² + y² exactly: the middle control point of x² over [-1, 1] is -1, so z_11 = -2.
  const SeparableSurface s = bezierToSeparable(2, 2, net);
  CHECK(evalPoint(s, 0.5, 0.5)(2) == doctest::Approx(0.0).scale(1.0));
  CHECK(evalPoint(s, 1.0, 0.5)(2) == doctest::Approx(1.0));
  const Mesh m = tessellate(s, 4, 4, true);
  const size_t centre = 2 * 5 + 2;
  CHECK(m.gaussCurvature[centre] == doctest::Approx(4.0).epsilon(1e-6));
  CHECK(m.meanCurvature[centre] == doctest::Approx(2.0).epsilon(1e-6));  // X_u × X_v points up (+z)
  // Away from the centre: K = 4 / (1 + 4x² + 4y²)².
  const size_t corner = 4 * 5 + 4;  // x = y = 1
  CHECK(m.gaussCurvature[corner] == doctest::Approx(4.0 / 81.0).epsilon(1e-6));
}
