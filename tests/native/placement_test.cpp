// Scene version 4 placements (scene/placement.hpp): a placed surface is the unplaced one moved
// by T + R·s (checked against Eigen's own rotations); a blend between surfaces placed by one
// rigid motion is that motion of the unplaced blend (the PDE is linear and kills constants);
// a blend by reference follows one surface moved alone and keeps its promise by the join
// certificate; bad placements are named errors.
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

constexpr double kPi = 3.14159265358979323846;

json example(const std::string& id) {
  json j = json::parse(readText(examplePath(id + ".json")));
  j["version"] = 4;
  return j;
}

json& patchNamed(json& scene, const std::string& name) {
  for (json& p : scene["patches"])
    if (p["name"] == name) return p;
  throw std::runtime_error("no patch " + name);
}

struct Motion {
  Eigen::Vector3d t;
  Eigen::Vector3d deg;
  double s;
  json field() const { return {{"translate", {t[0], t[1], t[2]}}, {"rotate", {deg[0], deg[1], deg[2]}}, {"scale", s}}; }
  // Independently of the core: three.js's Euler 'XYZ' is the rotation about x, then y, then z
  // applied in that order to the frame, i.e. the matrix Rx·Ry·Rz.
  Eigen::Vector3d apply(const Eigen::Vector3d& x) const {
    const Eigen::Matrix3d r = (Eigen::AngleAxisd(deg[0] * kPi / 180, Eigen::Vector3d::UnitX()) *
                               Eigen::AngleAxisd(deg[1] * kPi / 180, Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(deg[2] * kPi / 180, Eigen::Vector3d::UnitZ())).toRotationMatrix();
    return t + r * (s * x);
  }
};

Motion randomMotion(std::mt19937& rng) {
  std::uniform_real_distribution<double> pos(-3, 3), ang(-180, 180), sc(0.3, 3);
  return {{pos(rng), pos(rng), pos(rng)}, {ang(rng), ang(rng), ang(rng)}, sc(rng)};
}

// Largest |motion(a(u, v)) - b(u, v)| over a 33×33 grid, relative to b's size.
double movedDifference(const SeparableSurface& a, const SeparableSurface& b, const Motion& m, double u0 = 0, double u1 = 1) {
  double diff = 0, size = 0;
  for (int i = 0; i <= 32; ++i)
    for (int j = 0; j <= 32; ++j) {
      const double u = u0 + (u1 - u0) * i / 32.0, v = a.v0 + (a.v1 - a.v0) * j / 32.0;
      const Eigen::Vector3d q = evalPoint(b, u, v);
      diff = std::max(diff, (m.apply(evalPoint(a, u, v)) - q).norm());
      size = std::max(size, q.norm());
    }
  return diff / size;
}

std::string errorOf(const json& j) { return parseErrorOf(j.dump()); }

}  // namespace

TEST_CASE("placement: a placed surface is T + R s X, and a blend between surfaces moved together moves with them") {
  std::mt19937 rng(20261201);
  for (const char* id : {"ref-sphere-fillet", "ref-torus-plane"}) {
    const json base = example(id);
    const Scene s0 = parseScene(base.dump());
    const auto r0 = solveScene(s0);
    for (int draw = 0; draw < 8; ++draw) {
      CAPTURE(id);
      CAPTURE(draw);
      const Motion m = randomMotion(rng);
      json moved = base;
      for (json& p : moved["patches"])
        if (p["kind"] == "surface") p["placement"] = m.field();
      const Scene s1 = parseScene(moved.dump());
      const auto r1 = solveScene(s1);
      for (const SolvedPatch& p : r0) {
        CAPTURE(p.patch->name);
        CHECK(movedDifference(p.surface, solvedNamed(r1, p.patch->name).surface, m, p.surface.u0, p.surface.u1) < 1e-12);
      }
      CHECK(checkScene(s1, r1, 0).ok);
    }
  }
}

TEST_CASE("placement: a blend by reference follows one surface moved alone and stays G1 / G2") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> small(-0.4, 0.4), tilt(-20, 20);
  int joins = 0;
  double worstG1 = 0;
  for (int draw = 0; draw < 12; ++draw) {
    CAPTURE(draw);
    json scene = example("ref-sphere-fillet");
    const Motion m{{small(rng), small(rng), small(rng)}, {tilt(rng), tilt(rng), tilt(rng)}, 1.0 + small(rng) / 2};
    patchNamed(scene, "sphere")["placement"] = m.field();
    if (draw % 2) {
      patchNamed(scene, "fillet")["ends"]["u1"]["continuity"] = "curvature";
      patchNamed(scene, "fillet").erase("operator");  // order 6 by default
    }
    const Scene parsed = parseScene(scene.dump());
    const SceneReport r = checkScene(parsed, solveScene(parsed), 0);
    for (const JoinResult& j : r.joins) {
      CAPTURE(j.surface);
      CHECK(j.ok);
      CHECK(j.g0 < 1e-12);
      if (j.level >= 1) CHECK(j.g1Deg < 1e-8);
      if (j.level >= 1) worstG1 = std::max(worstG1, j.g1Deg);
      ++joins;
    }
  }
  CHECK(joins == 24);
  MESSAGE("worst G1 over " << joins << " joins with a moved sphere: " << worstG1 << " degrees");
}

TEST_CASE("placement: whole quarter turns are exact and keep the surface's terms") {
  json scene = example("ref-sphere-fillet");
  const Scene before = parseScene(scene.dump());
  patchNamed(scene, "sphere")["placement"] = {{"rotate", {0, 0, 90}}};
  const Scene after = parseScene(scene.dump());
  const auto& a = before.find("sphere")->primary();
  const auto& b = after.find("sphere")->primary();
  CHECK(b.terms[0].size() == a.terms[1].size());  // x' = -y
  CHECK(b.terms[1].size() == a.terms[0].size());  // y' = x
  CHECK(b.terms[2].size() == a.terms[2].size());
}

TEST_CASE("placement: parameters drive it, and the identity changes nothing") {
  json scene = example("ref-sphere-fillet");
  scene["parameters"]["lift"] = {{"value", 0.25}, {"min", 0}, {"max", 1}};
  patchNamed(scene, "sphere")["placement"] = {{"translate", {0, 0, "lift"}}};
  const Scene lifted = parseScene(scene.dump());
  const auto r = solveScene(lifted);
  json plain = example("ref-sphere-fillet");
  patchNamed(plain, "sphere")["placement"] = {{"translate", {0, 0, 0}}, {"rotate", {0, 0, 0}}, {"scale", 1}};
  const Scene unlifted = parseScene(plain.dump());
  const auto r0 = solveScene(unlifted);
  const Motion lift{{0, 0, 0.25}, {0, 0, 0}, 1};
  const SeparableSurface& s0 = solvedNamed(r0, "sphere").surface;
  CHECK(movedDifference(s0, solvedNamed(r, "sphere").surface, lift, s0.u0, s0.u1) < 1e-15);
}

TEST_CASE("placement: bad placements are named errors") {
  const json base = example("ref-sphere-fillet");
  auto with = [&](const json& placement, int version = 4) {
    json s = base;
    s["version"] = version;
    patchNamed(s, "sphere")["placement"] = placement;
    return errorOf(s);
  };
  CHECK(with({{"translate", {1, 0, 0}}}, 3) == "InvalidField: patches[2].placement: a placement needs scene version 4");
  CHECK(with({{"scale", 0}}) == "InvalidField: patches[2].placement.scale: a scale of 0 flattens the surface");
  CHECK(with({{"scale", {1, 0, 1}}}) == "InvalidField: patches[2].placement.scale: a scale of 0 flattens the surface");
  CHECK(with({{"translate", {1, 2}}}) == "InvalidField: patches[2].placement.translate: expected an array of three numbers [x, y, z]");
  CHECK(with({{"translate", {1, "1/0", 0}}}).rfind("NonFinite: patches[2].placement.translate[1]", 0) == 0);
  CHECK(with({{"rotate", {1e300, 0, 0}}}).rfind("InvalidField: patches[2].placement.rotate[0]", 0) == 0);
  CHECK(with({{"shear", 1}}) == "InvalidField: patches[2].placement.shear: unknown field");
  CHECK(with(json::array({1, 2, 3})) == "InvalidField: patches[2].placement: expected an object {translate, rotate, scale}");
  CHECK(with({{"scale", "nope"}}).rfind("UnknownName: patches[2].placement.scale", 0) == 0);
  json v5 = base;
  v5["version"] = 5;
  CHECK(errorOf(v5) == "InvalidField: version: this build reads scene versions 1 to 4");
}
