// The watertight mesh (issue 36, analysis/watertight_mesh.hpp), judged as a printer's slicer
// would: every edge of a closed body's mesh used exactly twice and in opposite directions, no
// edge on three triangles, no zero triangle, its volume outward and (Richardson over two
// grids) the exact surfaces' within 1e-4; an open body's free edges exactly its open borders;
// a model with a gap is not closed.
#include <doctest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <random>

#include "analysis/bodies.hpp"
#include "analysis/join_certificate.hpp"
#include "analysis/watertight_mesh.hpp"
#include "scene/scene.hpp"
#include "random_holes.hpp"
#include "test_util.hpp"

using namespace pdesurf;
using namespace pdesurf::testing;
using json = nlohmann::json;

namespace {

struct BodyMesh {
  size_t triangles = 0, zeroTriangles = 0;
  size_t freeEdges = 0;        // used by one triangle
  size_t sameWayTwice = 0;     // a directed edge used twice: two triangles facing apart
  size_t overused = 0;         // on three or more triangles
  double volume = 0;           // (1/6) Σ a · (b × c)
  double area = 0;
};

BodyMesh inspect(const ModelMesh& m, int body) {
  BodyMesh r;
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  const auto P = [&](uint32_t v) { return Eigen::Vector3d(m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]); };
  for (const ModelMesh::Part& part : m.parts) {
    if (part.body != body) continue;
    for (size_t t = 0; t < part.indices.size(); t += 3) {
      const uint32_t a = part.indices[t], b = part.indices[t + 1], c = part.indices[t + 2];
      ++r.triangles;
      r.zeroTriangles += a == b || b == c || a == c;
      for (const auto& e : {std::make_pair(a, b), std::make_pair(b, c), std::make_pair(c, a)}) ++directed[e];
      r.volume += P(a).dot(P(b).cross(P(c))) / 6;
      r.area += (P(b) - P(a)).cross(P(c) - P(a)).norm() / 2;
    }
  }
  for (const auto& [e, n] : directed) {
    r.sameWayTwice += n > 1;
    const auto back = directed.find({e.second, e.first});
    const int uses = n + (back == directed.end() ? 0 : back->second);
    if (e.first < e.second || back == directed.end()) {
      r.freeEdges += uses == 1;
      r.overused += uses > 2;
    }
  }
  return r;
}

struct Solved {
  Scene scene;
  std::vector<SolvedPatch> solved;
  double size = 0;
};

Solved solvedFrom(const std::string& text) {
  Solved s{parseScene(text), {}, 0};
  s.solved = solveScene(s.scene);
  s.size = sceneSizeOf(s.solved);
  return s;
}

// Every body as the bodies say: closed ones without a free edge, every edge twice and the
// triangles facing one way; with rel > 0, the area's and a closed body's volume's Richardson
// extrapolations from grids n, 2n against the exact surfaces' within rel (the mesh's own
// errors are O(h²): the aeroplane's volume 0.87, 0.23, 0.060, 0.015 at n = 16 .. 128).
void checkModel(const Solved& s, int n, double rel) {
  const std::vector<Body> bodies = measureBodies(s.solved, s.size);
  const ModelMesh coarse = watertightMesh(s.solved, s.size, n, n), fine = watertightMesh(s.solved, s.size, 2 * n, 2 * n);
  REQUIRE(fine.parts.size() == s.solved.size());
  for (size_t b = 0; b < bodies.size(); ++b) {
    CAPTURE(b);
    CAPTURE(bodies[b].patches.front());
    const BodyMesh c = inspect(coarse, int(b)), f = inspect(fine, int(b));
    CHECK(f.triangles > 0);
    CHECK(f.zeroTriangles == 0);
    CHECK(f.sameWayTwice == 0);
    CHECK(f.overused == 0);
    CHECK(c.sameWayTwice == 0);
    if (bodies[b].closed) {
      CHECK(c.freeEdges == 0);
      CHECK(f.freeEdges == 0);
      const double richardson = (4 * f.volume - c.volume) / 3;
      CAPTURE(c.volume);
      CAPTURE(f.volume);
      CAPTURE(bodies[b].volume);
      CHECK(f.volume > 0);  // outward
      if (rel > 0) CHECK(std::abs(richardson - bodies[b].volume) <= rel * bodies[b].volume);
    } else {
      CHECK(f.freeEdges > 0);
    }
    if (rel > 0) CHECK(std::abs((4 * f.area - c.area) / 3 - bodies[b].area) <= rel * bodies[b].area);
  }
}

}  // namespace

TEST_CASE("watertight meshes: a sphere (poles and a seam) and an open tube") {
  const Solved s = solvedFrom(R"json({"format": "pdesurf-scene", "version": 4, "patches": [
    {"name": "ball", "kind": "surface", "t_range": [0, "pi"], "v_range": [0, "2*pi"],
     "x": "1.5*sin(t)*cos(v)", "y": "1.5*sin(t)*sin(v)", "z": "1.5*cos(t)"},
    {"name": "tube", "kind": "surface", "t_range": [0, 2], "v_range": [0, "2*pi"], "x": "5 + 0.5*cos(v)", "y": "0.5*sin(v)", "z": "t"}]})json");
  checkModel(s, 32, 1e-4);
  const ModelMesh m = watertightMesh(s.solved, s.size, 8, 8);
  // The tube's free edges are its two rings, 8 cells each; the ball's poles one vertex each.
  CHECK(inspect(m, 1).freeEdges == 16);
  CHECK(inspect(m, 0).freeEdges == 0);
  CHECK_THROWS_AS(watertightMesh(s.solved, s.size, 2, 8), Error);
}

TEST_CASE("watertight meshes of every example: the bodies' verdicts, manifold and one-way") {
  const auto index = json::parse(readText(examplePath("index.json")));
  for (const auto& entry : index["examples"]) {
    const std::string file = entry["file"].get<std::string>();
    CAPTURE(file);
    const Solved s = solvedFrom(readText(examplePath(file)));
    checkModel(s, 12, 0);
  }
}

TEST_CASE("the aeroplane and the bottle: one closed mesh each, the exact volume within 1e-4") {
  checkModel(solvedFrom(readText(examplePath("you2004-fig8d.json"))), 64, 1e-4);
  checkModel(solvedFrom(readText(examplePath("bottle-solid.json"))), 64, 1e-4);
}

TEST_CASE("random holes and capped frusta: open borders free, closed bodies watertight") {
  std::mt19937 rng(3607);
  std::uniform_real_distribution<double> coef(-0.3, 0.3), unit(0, 1);
  const int trials = kTimeScale > 1 ? 2 : 6;
  for (int trial = 0; trial < trials; ++trial) {
    const int n = 3 + trial;
    CAPTURE(n);
    const Solved hole = solvedFrom(randomHole(n, Sheet{coef(rng), coef(rng), coef(rng), 0.3 * coef(rng)}, rng, 0.5).dump());
    checkModel(hole, 8, 0);
    // Its free edges: each strip's outer border and two ends (3 n borders), 8 cells each.
    CHECK(inspect(watertightMesh(hole.solved, hole.size, 8, 8), 0).freeEdges == size_t(3 * n * 8));
    const double r0 = 0.6 + 0.6 * unit(rng), r1 = 0.6 + 0.6 * unit(rng), h = 1 + 2 * unit(rng);
    const json tube = cappedTube(r0, r1, h);
    checkModel(solvedFrom(tube.dump()), 32, 1e-4);
    // The mutations: a face left unshared (its own copies of its vertices) opens the mesh;
    // a cap on a copy of the tube lifted by 1e-3 leaves the tube's top ring free.
    const Solved capped = solvedFrom(tube.dump());
    ModelMesh m = watertightMesh(capped.solved, capped.size, 8, 8);
    REQUIRE(inspect(m, 0).freeEdges == 0);
    std::map<uint32_t, uint32_t> copy;
    for (uint32_t& v : m.parts[2].indices) {
      if (!copy.count(v)) {
        m.positions.insert(m.positions.end(), {m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]});
        copy[v] = uint32_t(m.vertexCount() - 1);
      }
      v = copy[v];
    }
    CHECK(inspect(m, 0).freeEdges == 2 * 8);  // the ring, once on the tube and once on the cap
    json lifted = tube;
    lifted["patches"].push_back(lifted["patches"][0]);
    lifted["patches"][3]["name"] = "lifted";
    lifted["patches"][3]["z"] = std::to_string(h) + "*t + 1e-3";
    lifted["patches"][2]["borders"][0]["patch"] = "lifted";
    const Solved open = solvedFrom(lifted.dump());
    const ModelMesh g = watertightMesh(open.solved, open.size, 8, 8);
    const std::vector<Body> bodies = measureBodies(open.solved, open.size);
    REQUIRE(bodies.size() == 2);
    for (int b = 0; b < 2; ++b) CHECK(inspect(g, b).freeEdges == 8);
  }
}
