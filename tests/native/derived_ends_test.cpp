// Blend ends by reference (scene version 3, scene/derived_ends.hpp): seed examples whose
// printed conditions have this form, rebuilt by naming their surfaces, agree with the
// hand-written versions; random blends between cylinders, cones, spheres, tori and explicit
// surfaces, met at iso-lines and along curves, keep the continuity each end asks for by the
// join certificate, without folds; the extra conditions of an end that asks less are the
// ruled surface's; bad references are named errors.
#include <doctest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>

#include "analysis/join_certificate.hpp"
#include "common/errors.hpp"
#include "methods/method.hpp"
#include "scene/scene.hpp"
#include "test_util.hpp"

using namespace pdesurf;
using namespace pdesurf::testing;
using json = nlohmann::json;

namespace {

json example(const std::string& id) { return json::parse(readText(examplePath(id + ".json"))); }

json end(const std::string& surface, json at, const std::string& continuity, json power = 1, const std::string& scale = "surface") {
  return {{"surface", surface}, {"at", at}, {"continuity", continuity}, {"power", power}, {"scale", scale}};
}

// The example with its blend's (patches[0]) typed conditions replaced by `ends`, version 3.
json byReference(json scene, const json& ends) {
  scene["version"] = 3;
  scene["patches"][0].erase("boundary");
  scene["patches"][0]["ends"] = ends;
  for (json& p : scene["patches"]) p.erase("meets");  // derived from the ends now
  return scene;
}

// Largest difference between the two scenes' blends over a 41×41 grid, relative to the size.
double blendDifference(const json& a, const json& b) {
  const Scene sa = parseScene(a.dump()), sb = parseScene(b.dump());
  const auto ra = solveScene(sa), rb = solveScene(sb);
  const SeparableSurface& x = solvedNamed(ra, "blend").surface;
  const SeparableSurface& y = solvedNamed(rb, "blend").surface;
  double diff = 0.0, size = 0.0;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j) {
      const double u = i / 40.0, v = x.v0 + (x.v1 - x.v0) * j / 40.0;
      const Eigen::Vector3d p = evalPoint(x, u, v), q = evalPoint(y, u, v);
      diff = std::max(diff, (p - q).norm());
      size = std::max(size, p.norm());
    }
  return diff / size;
}

SceneReport certify(const json& j) {
  const Scene scene = parseScene(j.dump());
  return checkScene(scene, solveScene(scene), 0);
}

std::string errorOf(const json& j) {
  try {
    certify(j);
  } catch (const Error& e) {
    return std::string(errorCodeName(e.code())) + ": " + e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("by reference: seed examples rebuilt by naming their surfaces agree with the printed conditions") {
  SUBCASE("seed 000 Fig. 2a and 2b: cone frustum into a plane") {
    for (const char* id : {"you2004-fig2a", "you2004-fig2b"}) {
      CAPTURE(id);
      const json a = example(id);
      const json b = byReference(a, {{"u0", end("plane", "t0", "tangency")}, {"u1", end("cone", "t0", "tangency")}});
      CHECK(blendDifference(a, b) < 1e-12);
    }
  }
  SUBCASE("seed 000 Fig. 4a: a cylinder met along the space curve z = h0 + h1 sin(v/2)") {
    const json a = example("you2004-fig4a");
    json b = byReference(a, {{"u0", end("cylinder", {{"t", "h0 + h1*sin(0.5*v)"}}, "tangency", "h0p + h1p*sin(0.5*v)")},
                             {"u1", end("plane", "t0", "tangency", "Rp")}});
    b["patches"][1]["z"] = "t";  // the plain cylinder, trimmed by the curve
    b["patches"][1]["t_range"] = json::array({0, 3});
    CHECK(blendDifference(a, b) < 1e-12);
    const SceneReport r = certify(b);
    CHECK(r.joins.size() == 2);
    for (const JoinResult& j : r.joins) CHECK(j.ok);
  }
  SUBCASE("seed 003: the C² blends (curvature continuity at both ends)") {
    struct Case {
      const char* id;
      json ends;
    } cases[] = {
        {"zhang-c2-ex1", {{"u0", end("cylinder", "t0", "curvature")}, {"u1", end("sphere", "t0", "curvature")}}},
        {"zhang-c2-ex2", {{"u0", end("plane", "t1", "curvature")}, {"u1", end("cylinder", "t0", "curvature")}}},
        {"zhang-c2-ex3", {{"u0", end("plane", "t1", "curvature", "s")}, {"u1", end("cylinder", "t0", "curvature")}}},
    };
    for (const Case& c : cases) {
      CAPTURE(c.id);
      const json a = example(c.id);
      const json b = byReference(a, c.ends);
      CHECK(blendDifference(a, b) < 1e-12);
      const SceneReport r = certify(b);
      for (const JoinResult& j : r.joins) {
        CAPTURE(j.surface);
        CHECK(j.level == 2);
        CHECK(j.ok);
      }
    }
  }
}

namespace {

// A random cylinder, cone, sphere zone, torus zone or explicit surface around the z axis,
// as expressions in t and v, met at t = 0 (or along a curve near it). Each leaves its
// trimline away from the blend (downwards for the lower one, `above` false; upwards for the
// upper one), as a designer places surfaces to be blended.
json randomSurface(std::mt19937& rng, const std::string& name, bool above, double z) {
  std::uniform_real_distribution<double> U(0, 1);
  const auto n = [&](double lo, double hi) { return lo + (hi - lo) * U(rng); };
  const auto str = [](double x) { std::ostringstream s; s.precision(17); s << x; return s.str(); };
  json s = {{"name", name}, {"kind", "surface"}, {"v_range", json::array({0, "2*pi"})}, {"t_range", json::array({0, 1})}};
  const double R = n(0.8, 1.6), sg = above ? 1.0 : -1.0;
  const std::string zs = str(z), sgs = str(sg);
  switch (std::uniform_int_distribution<int>(0, 4)(rng)) {
    case 0:  // cylinder
      s["x"] = str(R) + "*cos(v)", s["y"] = str(R) + "*sin(v)", s["z"] = zs + " + " + sgs + "*t";
      break;
    case 1: {  // cone, widening or narrowing
      const std::string r = "(" + str(R) + " + " + str(n(-0.4, 0.4)) + "*t)";
      s["x"] = r + "*cos(v)", s["y"] = r + "*sin(v)", s["z"] = zs + " + " + sgs + "*t";
      break;
    }
    case 2: {  // sphere zone from the trimline's polar angle a0 towards the pole away from the blend
      const double rho = n(1.0, 1.6), a0 = n(0.6, 1.2);
      const std::string th = "(" + str(a0) + " - t)";
      s["x"] = str(rho) + "*sin" + th + "*cos(v)", s["y"] = str(rho) + "*sin" + th + "*sin(v)";
      s["z"] = str(z - sg * rho * std::cos(a0)) + " + " + str(sg * rho) + "*cos" + th;
      s["t_range"] = json::array({0, a0 - 0.2});
      break;
    }
    case 3: {  // torus zone: from the tube's outermost circle away from the blend
      const double Rt = n(1.0, 1.4), r = n(0.2, 0.4);
      s["x"] = "(" + str(Rt) + " + " + str(r) + "*cos(t))*cos(v)", s["y"] = "(" + str(Rt) + " + " + str(r) + "*cos(t))*sin(v)";
      s["z"] = zs + " + " + str(sg * r) + "*sin(t)";
      s["t_range"] = json::array({0, "pi/2"});
      break;
    }
    default: {  // explicit surface z = f(x, y) over an annulus, wavy, sloping away
      s["x"] = "(" + str(R) + " + t)*cos(v)", s["y"] = "(" + str(R) + " + t)*sin(v)";
      s["z"] = zs + " + " + str(n(-0.1, 0.1)) + "*cos(2*v) + " + sgs + "*(0.3*t + 0.2*t^2)";
      break;
    }
  }
  return s;
}

}  // namespace

TEST_CASE("by reference: random blends keep the continuity each end asks for, without folds") {
  std::mt19937 rng(20261130);
  const char* levels[3] = {"position", "tangency", "curvature"};
  int curves = 0, joins = 0;
  double worstG0 = 0.0, worstG1 = 0.0, worstG2 = 0.0;
  for (int trial = 0; trial < 40; ++trial) {
    CAPTURE(trial);
    json lower = randomSurface(rng, "lower", false, 0.0);
    json upper = randomSurface(rng, "upper", true, 1.5);
    json ends = json::object();
    for (int e = 0; e < 2; ++e) {
      json& s = e == 0 ? lower : upper;
      const int level = std::uniform_int_distribution<int>(0, 2)(rng);
      json at = "t0";
      if (std::uniform_int_distribution<int>(0, 2)(rng) == 0) {  // a curve trimline inside t_range
        at = {{"t", "0.18 + 0.12*sin(2*v)"}};
        ++curves;
      }
      std::uniform_real_distribution<double> P(0.6, 1.6);
      ends[e == 0 ? "u0" : "u1"] = end(s["name"], at, levels[level], P(rng), "gap");
    }
    const json scene = {{"format", "pdesurf-scene"}, {"version", 3},
                        {"patches", json::array({{{"name", "blend"}, {"kind", "pde"}, {"v_range", json::array({0, "2*pi"})}, {"ends", ends}}, lower, upper})}};
    const SceneReport r = certify(scene);
    REQUIRE(r.joins.size() == 2);
    for (const JoinResult& j : r.joins) {
      CAPTURE(scene.dump());
      CAPTURE(j.surface);
      CAPTURE(j.g0);
      CAPTURE(j.g1Deg);
      CAPTURE(j.g2Rel);
      CHECK(j.ok);
      CHECK(!j.fold);
      ++joins;
      worstG0 = std::max(worstG0, j.g0);
      if (j.level >= 1) worstG1 = std::max(worstG1, j.g1Deg);
      if (j.level >= 2) worstG2 = std::max(worstG2, j.g2Rel);
    }
  }
  CHECK(curves >= 10);
  MESSAGE(joins << " joins certified, " << curves << " ends along curve trimlines; worst G0 " << worstG0 << ", G1 " << worstG1
                << " deg, G2 " << worstG2);
}

TEST_CASE("by reference: an end that asks less than the operator carries gets the ruled surface's conditions") {
  // u0 position only, u1 curvature: order 6; at u0 X_u = X(1) - X(0) and X_uu = 0.
  const json a = byReference(example("zhang-c2-ex1"), {{"u0", end("cylinder", "t0", "position")}, {"u1", end("sphere", "t0", "curvature")}});
  const Scene scene = parseScene(a.dump());
  const Patch& blend = *scene.find("blend");
  for (int c = 0; c < 3; ++c) CHECK(blend.op()[c].order == 6);
  const auto solved = solveScene(scene);
  const SeparableSurface& s = solvedNamed(solved, "blend").surface;
  double worst = 0.0;
  for (int j = 0; j <= 40; ++j) {
    const double v = s.v0 + (s.v1 - s.v0) * j / 40.0;
    const Eigen::Vector3d chord = evalPoint(s, 1, v) - evalPoint(s, 0, v);
    worst = std::max({worst, (evalPoint(s, 0, v, 1) - chord).norm(), evalPoint(s, 0, v, 2).norm()});
  }
  CHECK(worst < 1e-10);
  const SceneReport r = checkScene(scene, solved, 0);
  for (const JoinResult& j : r.joins) {
    CAPTURE(j.surface);
    CHECK(j.level == (j.surface == "cylinder" ? 0 : 2));
    CHECK(j.ok);
  }
}

TEST_CASE("by reference: power and flip") {
  // Power scales the tangent across the join; flip reverses it (the blend then folds back).
  const json base = example("you2004-fig2a");
  const auto tangentAt0 = [](const json& j) {
    const Scene s = parseScene(j.dump());
    return evalPoint(solvedNamed(solveScene(s), "blend").surface, 0, 0.3, 1);
  };
  const Eigen::Vector3d t1 = tangentAt0(byReference(base, {{"u0", end("plane", "t0", "tangency", 1)}, {"u1", end("cone", "t0", "tangency")}}));
  const Eigen::Vector3d t2 = tangentAt0(byReference(base, {{"u0", end("plane", "t0", "tangency", 2.5)}, {"u1", end("cone", "t0", "tangency")}}));
  CHECK((t2 - 2.5 * t1).norm() < 1e-12 * t1.norm());
  json flipped = byReference(base, {{"u0", end("plane", "t0", "tangency")}, {"u1", end("cone", "t0", "tangency")}});
  flipped["patches"][0]["ends"]["u0"]["flip"] = true;
  CHECK((tangentAt0(flipped) + t1).norm() < 1e-12 * t1.norm());
  const SceneReport r = certify(flipped);
  bool folded = false;
  for (const JoinResult& j : r.joins) folded = folded || (j.surface == "plane" && j.fold);
  CHECK(folded);
  // The gap scale: power 1 gives a mean tangent as long as the mean gap between the ends.
  const Scene g = parseScene(byReference(base, {{"u0", end("plane", "t0", "tangency", 1, "gap")}, {"u1", end("cone", "t0", "tangency", 1, "gap")}}).dump());
  const auto gs = solveScene(g);
  const SeparableSurface& s = solvedNamed(gs, "blend").surface;
  double gap = 0.0, tangent = 0.0;
  for (int j = 0; j < 129; ++j) {
    const double v = s.v0 + (s.v1 - s.v0) * j / 128.0;
    gap += (evalPoint(s, 1, v) - evalPoint(s, 0, v)).norm() / 129;
    tangent += evalPoint(s, 0, v, 1).norm() / 129;
  }
  CHECK(tangent == doctest::Approx(gap).epsilon(1e-9));
}

TEST_CASE("by reference: bad references are named errors naming the end and the v at fault") {
  const json base = example("you2004-fig2a");
  const auto with = [&](json u0) { return byReference(base, {{"u0", u0}, {"u1", end("cone", "t0", "tangency")}}); };
  CHECK(errorOf(with(end("nothing", "t0", "tangency"))) == "UnknownName: patches[0].ends.u0.surface: no patch named 'nothing'");
  CHECK(errorOf(with(end("blend", "t0", "tangency"))).find("InvalidField: patches[0].ends.u0.surface: 'blend' is a pde patch") == 0);
  CHECK(errorOf(with(end("plane", {{"t", "0.6 + sin(v)"}}, "tangency"))).find("InvalidField: patches[0].ends.u0.at: the trimline t = ") == 0);
  CHECK(errorOf(with(end("plane", {{"t", "0.6 + sin(v)"}}, "tangency"))).find("at v = ") != std::string::npos);
  json flat = with(end("plane", "t0", "tangency"));
  flat["patches"][1]["x"] = "r0*cos(v)";  // no t: dS/dt = 0
  flat["patches"][1]["y"] = "r0*sin(v)";
  CHECK(errorOf(flat).find("InvalidField: patches[0].ends.u0.at: dS/dt of 'plane' vanishes on the trimline at v = 0") == 0);
  json along = with(end("plane", "t0", "tangency"));
  along["patches"][1]["x"] = "r0*cos(v + t)";  // t runs along the trimline circle
  along["patches"][1]["y"] = "r0*sin(v + t)";
  CHECK(errorOf(along).find("is parallel to the trimline at v = ") != std::string::npos);
  json typedToo = with(end("plane", "t0", "tangency"));
  typedToo["patches"][0]["boundary"] = {{"x", {{"u0", json::array({"1"})}}}};
  CHECK(errorOf(typedToo).find("InvalidField: patches[0].boundary.x.u0: end u0 is given by reference") == 0);
  json low = with(end("plane", "t0", "curvature"));
  low["patches"][0]["operator"] = {{"order", 4}, {"b", 1}, {"c", 2}, {"d", 1}};
  CHECK(errorOf(low) == "InvalidField: patches[0].operator.order: curvature continuity at u0 needs an order-6 operator; x has order 4");
  json v2 = with(end("plane", "t0", "tangency"));
  v2["version"] = 2;
  CHECK(errorOf(v2) == "InvalidField: patches[0].ends: ends by reference need scene version 3");
  json narrow = with(end("plane", "t0", "tangency"));
  narrow["patches"][1]["v_range"] = json::array({0, 3});
  CHECK(errorOf(narrow).find("is not inside the v_range [0, 3] of 'plane'") != std::string::npos);
  json bad = with(end("plane", "t0", "tangency"));
  bad["patches"][0]["ends"]["u0"]["continuity"] = "smooth";
  CHECK(errorOf(bad).find("InvalidField: patches[0].ends.u0.continuity") == 0);
}

TEST_CASE("by reference: blends between closed-form families stay closed form") {
  for (const char* id : {"ref-sphere-fillet", "ref-offset-cylinders-g2", "ref-torus-plane"}) {
    CAPTURE(id);
    const Scene scene = parseScene(readText(examplePath(std::string(id) + ".json")));
    const auto solved = solveScene(scene);
    CHECK(methodName(solved.front().used) == "closed");
    CHECK(boundaryError(solved.front().patch->pde(), solved.front().surface) < 1e-12);
  }
  // The square root of the T-joint's pipe is no family: the general methods take over.
  const Scene tjoint = parseScene(readText(examplePath("ref-pipe-tjoint.json")));
  CHECK(methodName(solveScene(tjoint).front().used) != "closed");
}
