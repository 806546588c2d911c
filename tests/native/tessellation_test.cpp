// The vectorised tessellation (surface/row_frame.cpp, pieces of 256 points in chunks of 64,
// xyz interleaved four or eight points at a time) against point-by-point evaluation in
// double, with every vector copy the CPU runs (common/vector_clones.hpp): every example's
// patches and random typed surfaces of every mix of 0-2 terms per component (read without
// combining where the copy does), grids whose rows end inside a piece and inside a group of
// four, with and without curvature; and the first out-of-range point found in a later piece.
#include <doctest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>

#include "common/errors.hpp"
#include "common/vector_clones.hpp"
#include "scene/scene.hpp"
#include "surface/curvature.hpp"
#include "surface/mesh.hpp"
#include "surface/tabulation.hpp"
#include "test_util.hpp"

using namespace pdesurf;
using namespace pdesurf::testing;
using json = nlohmann::json;

namespace {

struct Worst {
  double position = 0, normal = 0, curvature = 0;
  long checkedNormals = 0, checkedCurvatures = 0;
  // Floats where the mesh without curvature (read without combining where the copy does) and
  // the one with it (combined rows) differ in position or normal: the two paths do the same
  // arithmetic (a component of no terms may give −0 against 0, which compare equal).
  long pathsDiffer = 0;
};

// Compares two meshes of one grid, without and with curvature, with the surface at the grid
// points (the tabulation's own u, v).
void compare(const SeparableSurface& s, const Mesh& plain, const Mesh& m, Worst& w) {
  for (size_t k = 0; k < m.positions.size(); ++k)
    w.pathsDiffer += (plain.positions[k] != m.positions[k]) + (plain.normals[k] != m.normals[k]);
  for (int j = 0; j <= m.nv; ++j)
    for (int i = 0; i <= m.nu; ++i) {
      const double u = i == m.nu ? s.u1 : s.u0 + (s.u1 - s.u0) * i / m.nu;
      const double v = j == m.nv ? s.v1 : s.v0 + (s.v1 - s.v0) * j / m.nv;
      const size_t k = static_cast<size_t>(j) * (m.nu + 1) + i;
      const Eigen::Vector3d X = evalPoint(s, u, v), Xu = evalPoint(s, u, v, 1, 0), Xv = evalPoint(s, u, v, 0, 1);
      for (const Mesh* mesh : {&plain, &m}) {
        const Eigen::Vector3d P(mesh->positions[3 * k], mesh->positions[3 * k + 1], mesh->positions[3 * k + 2]);
        // A float holds X to 2^-24 relative; the sums may differ from evalPoint's by rounding.
        w.position = std::max(w.position, (P - X).norm() / (1 + X.norm()));
      }
      const Eigen::Vector3d cross = Xu.cross(Xv);
      // Clear of poles (where the vertex borrows a neighbour's normal) and near-poles; a speed
      // at the rounding of the position is a pole too (a fill's corner: X_v = 1.8e-16, whose
      // direction is rounding noise in either evaluation).
      const double scale = 1 + X.norm();
      if (cross.squaredNorm() > 1e-12 * Xu.squaredNorm() * Xv.squaredNorm() && std::min(Xu.norm(), Xv.norm()) > 1e-12 * scale) {
        for (const Mesh* mesh : {&plain, &m}) {
          const Eigen::Vector3d N(mesh->normals[3 * k], mesh->normals[3 * k + 1], mesh->normals[3 * k + 2]);
          w.normal = std::max(w.normal, (N - cross.normalized()).norm());
          ++w.checkedNormals;
        }
        const Curvature c = curvatureAt(Xu, Xv, evalPoint(s, u, v, 2, 0), evalPoint(s, u, v, 1, 1), evalPoint(s, u, v, 0, 2));
        w.curvature = std::max(w.curvature, std::abs(m.meanCurvature[k] - c.H) / (1 + std::abs(c.H)));
        w.curvature = std::max(w.curvature, std::abs(m.gaussCurvature[k] - c.K) / (1 + std::abs(c.K)));
        ++w.checkedCurvatures;
      }
    }
}


// Rows of 2 points; of 6 (a group of four and two); of 263 (a piece of 256, a group of four
// and three).
constexpr int kGrids[][2] = {{1, 1}, {5, 2}, {262, 1}};

// Tessellates s on every grid, with and without curvature, and compares.
int tessellateAndCompare(const SeparableSurface& s, Worst& w) {
  for (const auto& g : kGrids) {
    Mesh plain, m;
    // Twice into one mesh: the reused path must overwrite everything it wrote.
    tessellateInto(s, g[1], g[0], m, false);
    tessellateInto(s, g[0], g[1], m, true);
    tessellateInto(s, g[0], g[1], plain, false);
    compare(s, plain, m, w);
  }
  return 2 * static_cast<int>(std::size(kGrids));
}

void checkWorst(const Worst& w, int meshes, int minMeshes, long minNormals) {
  MESSAGE(std::string(vectorCopyName(vectorCopy())) << ": " << meshes << " meshes; worst position " << w.position << ", normal " << w.normal
                                       << ", curvature " << w.curvature << " (" << w.checkedNormals << " normals, "
                                       << w.checkedCurvatures << " curvatures)");
  CHECK(meshes > minMeshes);
  CHECK(w.checkedNormals > minNormals);
  CHECK(w.position < 1e-6);
  CHECK(w.normal < 1e-5);
  CHECK(w.curvature < 1e-4);
  CHECK(w.pathsDiffer == 0);
}

// Runs body once with each vector copy, then restores the widest.
template <class Body>
void withEveryVectorCopy(Body&& body) {
  for (VectorCopy copy : availableVectorCopies()) {
    limitVectorCopy(copy);
    const std::string name = vectorCopyName(copy);
    CAPTURE(name);
    body();
  }
  limitVectorCopy(VectorCopy::Avx512);
}

// A component of `terms` separable terms (0, 1 or 2) with random coefficients; its tabulation
// is checked to hold that many.
std::string randomComponent(int terms, std::mt19937& rng) {
  std::uniform_real_distribution<double> U(0.3, 2.0);
  // Single factors: a sum such as (1+t*t) would be expanded into two terms.
  const char* uFactors[] = {"cos(t)", "t*t", "exp(t)", "sin(2*t)"};
  const char* vFactors[] = {"cos(v)", "sin(v)", "v*v", "cos(2*v)"};
  std::uniform_int_distribution<int> pick(0, 3);
  std::string e = terms == 0 ? "0" : "";
  for (int k = 0; k < terms; ++k) {
    // Term k's v-factor differs from the other term's, so the two stay two terms.
    e += (k ? " + " : "") + std::to_string(U(rng)) + "*" + uFactors[pick(rng)] + "*" + vFactors[(pick(rng) % 2) * 2 + k];
  }
  return e;
}

}  // namespace

TEST_CASE("tessellation: positions, normals and curvature agree with point evaluation, every example, odd grids") {
  const json index = json::parse(readText(examplePath("index.json")));
  // Under ASan and in wasm (the expression walker is 3-10x slower there), every third example.
#if defined(__EMSCRIPTEN__)
  const int stride = 3;
#else
  const int stride = kTimeScale > 1 ? 3 : 1;
#endif
  std::vector<SeparableSurface> surfaces;
  int n = 0;
  for (const auto& e : index["examples"]) {
    if (n++ % stride != 0) continue;
    const std::string file = e["file"];
    for (const SolvedPatch& sp : solveScene(parseScene(readText(examplePath(file))))) surfaces.push_back(sp.surface);
  }
  withEveryVectorCopy([&] {
    Worst w;
    int meshes = 0;
    for (const SeparableSurface& s : surfaces) meshes += tessellateAndCompare(s, w);
    checkWorst(w, meshes, 200 / stride, 100000 / stride);
  });
}

TEST_CASE("tessellation: random typed surfaces of every mix of 0, 1 and 2 terms per component, every vector copy") {
  std::mt19937 rng(21);
  std::vector<SeparableSurface> surfaces;
  for (int mix = 0; mix < 27; ++mix) {
    const int terms[3] = {mix % 3, mix / 3 % 3, mix / 9};
    if (terms[0] + terms[1] + terms[2] < 2) continue;  // no surface (a point or a line)
    const json scene = {{"format", "pdesurf-scene"},
                        {"version", 3},
                        {"patches",
                         {{{"name", "s"}, {"kind", "surface"}, {"x", randomComponent(terms[0], rng)}, {"y", randomComponent(terms[1], rng)},
                           {"z", randomComponent(terms[2], rng)}, {"t_range", json::array({"-0.7", "1.3"})}, {"v_range", json::array({0, "2*pi"})}}}}};
    surfaces.push_back(solveScene(parseScene(scene.dump())).at(0).surface);
    const Tabulation t = tabulate(surfaces.back(), 2, 2);
    CAPTURE(scene.dump());
    for (int c = 0; c < 3; ++c) CHECK(t.terms[c] == terms[c]);
  }
  withEveryVectorCopy([&] {
    Worst w;
    int meshes = 0;
    for (const SeparableSurface& s : surfaces) meshes += tessellateAndCompare(s, w);
    checkWorst(w, meshes, 100, 10000);
  });
}

TEST_CASE("tessellation: the first point beyond a float is named, also in a later piece") {
  // x = exp(100 t) passes 3.4e38 at t = ln(3.4028e38) / 100 = 0.88722: point 888 of 1001,
  // in the fourth piece of 256.
  auto surfaceUpTo = [](const char* t1) {
    const json scene = {{"format", "pdesurf-scene"},
                        {"version", 3},
                        {"patches",
                         {{{"name", "s"}, {"kind", "surface"}, {"x", "exp(100*t)"}, {"y", "cos(v)"}, {"z", "sin(v)"},
                           {"t_range", json::array({0, t1})}, {"v_range", json::array({0, "2*pi"})}}}}};
    return solveScene(parseScene(scene.dump())).at(0).surface;
  };
  Mesh m;
  CHECK_THROWS_WITH_AS(tessellateInto(surfaceUpTo("1"), 1000, 4, m),
                       "the surface at (t, v) = (0.888, 0) is beyond what a float holds (|x| > 3.4e38) or not finite", Error);
  tessellateInto(surfaceUpTo("0.887"), 1000, 4, m);  // every point fits, the last barely
  CHECK(m.positions[3 * 1000] > 3e38f);
}

TEST_CASE("tessellation: a curvature beyond a float is clamped to ±3e38, in every piece; one that fits is kept") {
  // A sphere of radius r: |H| = 1/r, K = 1/r². r = 1e-40 puts both beyond 3.4e38.
  auto sphereOfRadius = [](const char* r) {
    const std::string R = r;
    const json scene = {{"format", "pdesurf-scene"},
                        {"version", 3},
                        {"patches",
                         {{{"name", "s"}, {"kind", "surface"}, {"x", R + "*sin(t)*cos(v)"}, {"y", R + "*sin(t)*sin(v)"},
                           {"z", R + "*cos(t)"}, {"t_range", json::array({"0.3", "2.8"})}, {"v_range", json::array({0, "2*pi"})}}}}};
    return solveScene(parseScene(scene.dump())).at(0).surface;
  };
  Mesh m;
  tessellateInto(sphereOfRadius("1e-40"), 600, 3, m, true);
  size_t clampedH = 0, clampedK = 0;
  for (size_t k = 0; k < m.meanCurvature.size(); ++k) {
    clampedH += std::abs(m.meanCurvature[k]) == 3e38f;
    clampedK += m.gaussCurvature[k] == 3e38f;
  }
  CHECK(clampedH == m.meanCurvature.size());
  CHECK(clampedK == m.gaussCurvature.size());
  tessellateInto(sphereOfRadius("1e-15"), 600, 3, m, true);
  for (size_t k = 0; k < m.meanCurvature.size(); k += 97) {
    CHECK(std::abs(std::abs(m.meanCurvature[k]) - 1e15f) < 1e-4f * 1e15f);
    CHECK(std::abs(m.gaussCurvature[k] - 1e30f) < 1e-4f * 1e30f);
  }
}
