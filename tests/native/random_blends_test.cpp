// Blends by reference between the surfaces a designer brings, drawn at random over the whole
// space the scene format reaches (issue 17): cylinders, cones, plane annuli and strips, sphere
// and torus zones, bent pipes and explicit surfaces over discs and rectangles; iso-line and
// curve trimlines; every continuity per side; closed and open v-ranges; powers 0.3-3 as
// numbers and as expressions in v. Every join must keep its promise by the certificate
// (G0 1e-9 of the scene's size, G1 1e-6°, G2 1e-6) with no fold, whatever method auto picks;
// the interior's PDE residual is reported and bounded.
#include <doctest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "analysis/join_certificate.hpp"
#include "methods/measures.hpp"
#include "scene/scene.hpp"

using namespace pdesurf;
using json = nlohmann::json;

namespace {

std::string str(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

struct Draw {
  std::mt19937 rng;
  double real(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); }
};

struct Surface {
  json j;
  // Leaves its border sideways (planes, explicit surfaces): a position join there, whose
  // direction is the straight line to the other curve, is a crease that can fold back, so
  // a designer meets it with tangency or curvature.
  bool sideways = false;
  double t1 = 1.0;    // the t-range is [0, t1]
};

// A surface whose t = 0 border faces the blend: `up` +1 for the upper one (leaving upwards from
// height z), -1 for the lower. Around the z axis in v, or (`linear`, open ranges only) along
// x, as both surfaces of one blend are.
Surface randomSurface(Draw& d, const std::string& name, double up, double z, bool linear) {
  Surface s;
  s.j = {{"name", name}, {"kind", "surface"}, {"t_range", json::array({0, 1})}};
  const std::string Z = str(z), U = str(up), R = str(d.real(0.8, 1.6));
  switch (linear ? 8 + d.pick(4) : d.pick(8)) {
    case 0:  // cylinder
      s.j["x"] = R + "*cos(v)", s.j["y"] = R + "*sin(v)", s.j["z"] = Z + " + " + U + "*t";
      break;
    case 1: {  // cone
      const std::string r = "(" + R + " + " + str(d.real(-0.4, 0.4)) + "*t)";
      s.j["x"] = r + "*cos(v)", s.j["y"] = r + "*sin(v)", s.j["z"] = Z + " + " + U + "*t";
      break;
    }
    case 2: {  // plane annulus, a little tilted, widening away from the blend
      const std::string r = "(" + R + " + t)";
      s.j["x"] = r + "*cos(v)", s.j["y"] = r + "*sin(v)", s.j["z"] = Z + " + " + str(d.real(-0.15, 0.15)) + "*" + r + "*cos(v)";
      s.sideways = true;
      break;
    }
    case 3: {  // sphere zone from polar angle a0 towards the pole away from the blend
      const double rho = d.real(1.0, 1.6), a0 = d.real(0.6, 1.2);
      const std::string th = "(" + str(a0) + " - t)";
      s.j["x"] = str(rho) + "*sin" + th + "*cos(v)", s.j["y"] = str(rho) + "*sin" + th + "*sin(v)";
      s.j["z"] = str(z - up * rho * std::cos(a0)) + " + " + str(up * rho) + "*cos" + th;
      s.t1 = a0 - 0.2;
      break;
    }
    case 4: {  // torus zone from the tube's outermost circle
      const std::string Rt = str(d.real(1.0, 1.4)), r = str(d.real(0.2, 0.4));
      s.j["x"] = "(" + Rt + " + " + r + "*cos(t))*cos(v)", s.j["y"] = "(" + Rt + " + " + r + "*cos(t))*sin(v)";
      s.j["z"] = Z + " + " + str(up) + "*" + r + "*sin(t)";
      s.t1 = M_PI / 2;
      break;
    }
    case 5: {  // bent pipe: a circle swept along a curving axis
      const std::string bend = str(d.real(-0.4, 0.4));
      s.j["x"] = bend + "*t^2 + " + R + "*cos(v)", s.j["y"] = R + "*sin(v)", s.j["z"] = Z + " + " + U + "*t";
      break;
    }
    case 6: {  // ellipsoid zone
      const double a = d.real(0.9, 1.5), b = d.real(0.9, 1.5), c = d.real(0.8, 1.4), a0 = d.real(0.7, 1.2);
      const std::string th = "(" + str(a0) + " - t)";
      s.j["x"] = str(a) + "*sin" + th + "*cos(v)", s.j["y"] = str(b) + "*sin" + th + "*sin(v)";
      s.j["z"] = str(z - up * c * std::cos(a0)) + " + " + str(up * c) + "*cos" + th;
      s.t1 = a0 - 0.2;
      break;
    }
    case 7: {  // explicit z = f(x, y) over an annulus: wavy, sloping away, with a square root
      const std::string r = "(" + R + " + t)";
      s.j["x"] = r + "*cos(v)", s.j["y"] = r + "*sin(v)";
      s.j["z"] = Z + " + " + str(d.real(-0.1, 0.1)) + "*cos(2*v) + " + U + "*(0.2*t + 0.1*sqrt(1 + 0.3*(" + r + "*cos(v))^2 + t))";
      s.sideways = true;
      break;
    }
    case 8: {  // plane strip along x, a little tilted
      s.j["x"] = "v", s.j["y"] = str(d.real(-0.3, 0.3)) + " - t", s.j["z"] = Z + " + " + str(d.real(-0.2, 0.2)) + "*t";
      s.sideways = true;
      break;
    }
    case 9: {  // explicit z = f(x, y) over a rectangle, sloping away
      s.j["x"] = "v", s.j["y"] = str(up * d.real(0.2, 0.6)) + " + " + U + "*t";
      s.j["z"] = Z + " + " + U + "*(0.5*t + 0.2*t^2) + " + str(d.real(-0.15, 0.15)) + "*sin(2*v)*exp(-t)";
      s.sideways = true;
      break;
    }
    case 10: {  // vertical wall along x
      s.j["x"] = "v", s.j["y"] = str(d.real(-0.5, 0.5)), s.j["z"] = Z + " + " + U + "*t";
      break;
    }
    default: {  // wavy wall, leaning
      s.j["x"] = "v", s.j["y"] = str(d.real(-0.5, 0.5)) + " + " + str(d.real(0.05, 0.2)) + "*sin(2*v) + " + str(d.real(-0.3, 0.3)) + "*t";
      s.j["z"] = Z + " + " + U + "*t";
      break;
    }
  }
  s.j["t_range"] = json::array({0, s.t1});
  return s;
}

json randomTrimline(Draw& d, const Surface& s, bool open) {
  if (d.pick(3) > 0) return "t0";
  const double mid = d.real(0.15, 0.3) * s.t1, amp = d.real(0.2, 0.6) * mid;
  if (open && d.pick(2) == 0) return {{"t", str(mid) + " + " + str(amp) + "*sin(v)*v/4"}};  // not periodic
  return {{"t", str(mid) + " + " + str(amp) + "*sin(" + std::to_string(1 + d.pick(3)) + "*v)"}};
}

json randomPower(Draw& d) {
  if (d.pick(2) == 0) return d.real(0.3, 3.0);
  const double p = d.real(0.5, 1.8), q = d.real(0.05, 0.3) * p;
  return str(p) + " + " + str(q) + "*" + (d.pick(2) ? "sin(v)" : "cos(2*v)");
}

json randomScene(Draw& d, bool* open) {
  *open = d.pick(2) == 0;
  json vRange = json::array({0, "2*pi"});
  if (*open) {
    const double v0 = d.real(0.0, 1.0);
    vRange = json::array({v0, v0 + d.real(1.0, 3.0)});
  }
  const char* levels[3] = {"position", "tangency", "curvature"};
  json patches = json::array({{{"name", "blend"}, {"kind", "pde"}, {"v_range", vRange}}});
  json ends = json::object();
  const bool linear = *open && d.pick(3) == 0;
  for (int e = 0; e < 2; ++e) {
    Surface s = randomSurface(d, e ? "upper" : "lower", e ? 1.0 : -1.0, e ? 1.5 : 0.0, linear);
    s.j["v_range"] = vRange;
    const int level = s.sideways ? 1 + d.pick(2) : d.pick(3);
    ends[e ? "u1" : "u0"] = {{"surface", s.j["name"]}, {"at", randomTrimline(d, s, *open)}, {"continuity", levels[level]},
                             {"power", randomPower(d)}};
    patches.push_back(s.j);
  }
  patches[0]["ends"] = ends;
  return {{"format", "pdesurf-scene"}, {"version", 3}, {"patches", patches}};
}

}  // namespace

TEST_CASE("random blends by reference keep every promise at their joins, on open and closed ranges, whatever method solves them") {
  Draw d{std::mt19937(20261201)};
  constexpr int kScenes = 100;
  int joins = 0, open = 0, curves = 0, general = 0, byLevel[3] = {0, 0, 0};
  double worstG0 = 0.0, worstG1 = 0.0, worstG2 = 0.0, worstResidual = 0.0;
  for (int k = 0; k < kScenes; ++k) {
    bool isOpen = false;
    const json j = randomScene(d, &isOpen);
    CAPTURE(k);
    CAPTURE(j.dump());
    open += isOpen;
    for (const char* e : {"u0", "u1"}) curves += j["patches"][0]["ends"][e]["at"].is_object();
    const Scene scene = parseScene(j.dump());
    const std::vector<SolvedPatch> solved = solveScene(scene);
    const SceneReport r = checkScene(scene, solved, 0);
    REQUIRE(r.joins.size() == 2);
    for (const JoinResult& jr : r.joins) {
      CAPTURE(jr.surface);
      CAPTURE(jr.g0);
      CAPTURE(jr.g1Deg);
      CAPTURE(jr.g2Rel);
      CHECK(jr.ok);
      CHECK(!jr.fold);
      ++joins;
      ++byLevel[jr.level];
      worstG0 = std::max(worstG0, jr.g0);
      if (jr.level >= 1) worstG1 = std::max(worstG1, jr.g1Deg);
      if (jr.level >= 2) worstG2 = std::max(worstG2, jr.g2Rel);
    }
    const SolvedPatch& blend = solved.front();
    if (blend.used.kind != MethodKind::Closed) ++general;
    const PdeResidual res = interiorResidual(blend.patch->pde(), blend.surface);
    CAPTURE(methodName(blend.used));
    CHECK(res.relative < 1e-6);  // measured worst 1.5e-7 over 200 such scenes
    worstResidual = std::max(worstResidual, res.relative);
  }
  // The draw reaches what it should.
  CHECK(open >= 35);
  CHECK(curves >= 40);
  CHECK(general >= 25);
  for (int level = 0; level < 3; ++level) CHECK(byLevel[level] >= 30);
  MESSAGE(joins << " joins (" << byLevel[0] << " G0, " << byLevel[1] << " G1, " << byLevel[2] << " G2), " << open << " open ranges, "
                << curves << " curve trimlines, " << general << " solved by a general method; worst G0 " << worstG0 << ", G1 " << worstG1
                << " deg, G2 " << worstG2 << "; worst interior residual " << worstResidual);
}

TEST_CASE("open data whose high derivatives are not finite at an end still solve, with exact joins") {
  // v^2.5 has no finite third derivative at v = 0: the end match drops to the orders that exist.
  const json j = json::parse(R"({"format":"pdesurf-scene","version":3,"patches":[
    {"name":"blend","kind":"pde","v_range":[0,2],"ends":{"u0":{"surface":"lower","at":"t0","continuity":"tangency"},
                                                       "u1":{"surface":"upper","at":"t0","continuity":"tangency"}}},
    {"name":"lower","kind":"surface","v_range":[0,2],"t_range":[0,1],"x":"v","y":"-t","z":"0.3*v^2.5*t"},
    {"name":"upper","kind":"surface","v_range":[0,2],"t_range":[0,1],"x":"v","y":"1+t","z":"1.5+t+0.2*v^2.5"}]})");
  const Scene scene = parseScene(j.dump());
  const std::vector<SolvedPatch> solved = solveScene(scene);
  CHECK(solved.front().used.kind == MethodKind::Modal);
  const SceneReport r = checkScene(scene, solved, 0);
  REQUIRE(r.joins.size() == 2);
  for (const JoinResult& jr : r.joins) CHECK(jr.ok);
}
