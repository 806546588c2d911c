#include "analysis/crossings.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "common/errors.hpp"
#include "common/text.hpp"
#include "surface/mesh.hpp"

namespace pdesurf {

namespace {

struct Tri {
  int patch, i, j;  // cell (i, j) of the patch's grid
  Eigen::Vector3d a, b, c, lo, hi;
};

struct PatchGrid {
  const Patch* patch;
  double u0, u1, v0, v1;
  bool closedU = false, closedV = false;  // first and last grid lines coincide (seams)
};

// Segment pq against the interior of triangle abc (Möller-Trumbore, strict with margin eps).
bool segmentCrosses(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Tri& t, double eps) {
  const Eigen::Vector3d e1 = t.b - t.a, e2 = t.c - t.a, d = q - p;
  const Eigen::Vector3d h = d.cross(e2);
  const double det = e1.dot(h);
  if (std::abs(det) <= 1e-14 * e1.norm() * e2.norm() * d.norm()) return false;  // parallel: touching, not crossing
  const double f = 1.0 / det;
  const Eigen::Vector3d s = p - t.a;
  const double bu = f * s.dot(h);
  if (bu <= eps || bu >= 1 - eps) return false;
  const Eigen::Vector3d qv = s.cross(e1);
  const double bv = f * d.dot(qv);
  if (bv <= eps || bu + bv >= 1 - eps) return false;
  const double tt = f * e2.dot(qv);
  return tt > eps && tt < 1 - eps;
}

bool trianglesCross(const Tri& x, const Tri& y, double eps) {
  const Eigen::Vector3d* X[3] = {&x.a, &x.b, &x.c};
  const Eigen::Vector3d* Y[3] = {&y.a, &y.b, &y.c};
  for (int k = 0; k < 3; ++k) {
    if (segmentCrosses(*X[k], *X[(k + 1) % 3], y, eps)) return true;
    if (segmentCrosses(*Y[k], *Y[(k + 1) % 3], x, eps)) return true;
  }
  return false;
}

bool sharePoint(const Tri& x, const Tri& y, double tol) {
  const Eigen::Vector3d* X[3] = {&x.a, &x.b, &x.c};
  const Eigen::Vector3d* Y[3] = {&y.a, &y.b, &y.c};
  for (auto* p : X)
    for (auto* q : Y)
      if ((*p - *q).cwiseAbs().maxCoeff() <= tol) return true;
  return false;
}

// Within kContactRows cells of one of the patch's borders.
constexpr int kContactRows = 3;
bool nearBorder(const Tri& t, int grid) {
  return t.i < kContactRows || t.i >= grid - kContactRows || t.j < kContactRows || t.j >= grid - kContactRows;
}

// A patch's border resting on another surface with a common tangent plane (a blend meeting a
// surface along a curve that is not declared as a join, e.g. seed 000 Fig. 5): chords of the
// two meshes cross within a band that shrinks with the grid (3 rows at any grid). Nearly
// parallel triangles at a border are taken as that contact, not as a crossing.
bool tangentialContact(const Tri& x, const Tri& y, int grid) {
  if (!nearBorder(x, grid) && !nearBorder(y, grid)) return false;
  const Eigen::Vector3d nx = (x.b - x.a).cross(x.c - x.a).normalized(), ny = (y.b - y.a).cross(y.c - y.a).normalized();
  return std::abs(nx.dot(ny)) > std::cos(10.0 * M_PI / 180.0);
}

// Index distance along a grid direction of n cells, wrapping when the direction is closed.
int cellDistance(int a, int b, int n, bool closed) {
  const int d = std::abs(a - b);
  return closed ? std::min(d, n - d) : d;
}

// Every patch's grid × grid mesh as triangles (two per cell), its grid's seams noted.
struct Meshes {
  std::vector<PatchGrid> grids;
  std::vector<Tri> tris;
  double edgeSum = 0.0;
};

// Patch p's grid × grid mesh into m (m.grids sized for every patch).
void addMesh(Meshes& m, const std::vector<SolvedPatch>& solved, int p, int grid, double tol) {
  const SeparableSurface& s = solved[p].surface;
  const GridSamples g = sampleGrid(s, grid, grid);
  auto at = [&](int i, int j) { return Eigen::Vector3d(&g.X[3 * (static_cast<size_t>(j) * (grid + 1) + i)]); };
  PatchGrid& pg = m.grids[p];
  pg = {solved[p].patch, s.u0, s.u1, s.v0, s.v1};
  pg.closedU = pg.closedV = true;
  for (int k = 0; k <= grid; ++k) {
    pg.closedV = pg.closedV && (at(k, 0) - at(k, grid)).norm() <= tol;
    pg.closedU = pg.closedU && (at(0, k) - at(grid, k)).norm() <= tol;
  }
  for (int j = 0; j < grid; ++j)
    for (int i = 0; i < grid; ++i) {
      const Eigen::Vector3d a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      for (const auto& t3 : {std::array<Eigen::Vector3d, 3>{a, b, c}, std::array<Eigen::Vector3d, 3>{a, c, d}}) {
        Tri t{p, i, j, t3[0], t3[1], t3[2], t3[0].cwiseMin(t3[1]).cwiseMin(t3[2]), t3[0].cwiseMax(t3[1]).cwiseMax(t3[2])};
        m.edgeSum += (t.hi - t.lo).norm();
        m.tris.push_back(t);
      }
    }
}

// Triangles of a uniform spatial hash's cells (about twice a triangle's size), and the pairs
// the test would compare: Σ n(n-1)/2 over the cells, known before any pair is compared.
struct Hash {
  double h = 1.0;
  std::unordered_map<int64_t, std::vector<int>> buckets;
  double pairs = 0.0;
  static int64_t key(int x, int y, int z) { return (static_cast<int64_t>(x) * 73856093) ^ (static_cast<int64_t>(y) * 19349663) ^ (static_cast<int64_t>(z) * 83492791); }
  int cellOf(double x) const { return static_cast<int>(std::floor(x / h)); }
};

// Triangle k into the hash's cells (hash.h set).
void hashTriangle(Hash& hash, const Meshes& m, int k) {
  const Tri& t = m.tris[k];
  for (int x = hash.cellOf(t.lo.x()); x <= hash.cellOf(t.hi.x()); ++x)
    for (int y = hash.cellOf(t.lo.y()); y <= hash.cellOf(t.hi.y()); ++y)
      for (int z = hash.cellOf(t.lo.z()); z <= hash.cellOf(t.hi.z()); ++z) hash.buckets[Hash::key(x, y, z)].push_back(k);
}

// The densest cell's first two patches, for the error when the pairs stay over the limit.
std::string densestPair(const Meshes& m, const Hash& hash, const std::vector<SolvedPatch>& solved) {
  const std::vector<int>* densest = nullptr;
  for (const auto& [key, b] : hash.buckets)
    if (!densest || b.size() > densest->size()) densest = &b;
  if (!densest || densest->empty()) return "";
  const int a = m.tris[size_t(densest->front())].patch;
  for (int k : *densest)
    if (m.tris[size_t(k)].patch != a) return "'" + solved[a].patch->name + "' and '" + solved[m.tris[size_t(k)].patch].patch->name + "'";
  return "'" + solved[a].patch->name + "' with itself";
}

// All three corners of x at corners of y: the two patches coincide there.
bool sameTriangle(const Tri& x, const Tri& y, double tol) {
  for (const Eigen::Vector3d* p : {&x.a, &x.b, &x.c}) {
    bool found = false;
    for (const Eigen::Vector3d* q : {&y.a, &y.b, &y.c}) found = found || (*p - *q).cwiseAbs().maxCoeff() <= tol;
    if (!found) return false;
  }
  return (x.b - x.a).cross(x.c - x.a).norm() > tol * tol;  // a cell that is a point or a line covers nothing
}

}  // namespace

// The search's state between steps: the meshes patch by patch, the hash block by block, then
// the triangles' pairs block by block.
struct CrossingSearch::State {
  enum class Stage { Mesh, Hash, Pairs, Done };
  const std::vector<SolvedPatch>& solved;
  int P, grid;
  double size, tol;
  Stage stage = Stage::Mesh;
  int next = 0;  // the next patch (Mesh) or triangle (Hash, Pairs)
  Meshes meshes;
  Hash hash;
  std::vector<int> stamp;
  std::vector<Crossing> found;
  std::unordered_map<int64_t, size_t> foundAt;  // (patch, other) -> its entry in found

  State(const std::vector<SolvedPatch>& s, double sceneSize, int askedGrid)
      : solved(s), P(static_cast<int>(s.size())), size(sceneSize), tol(1e-9 * sceneSize) {
    // Bounded before the work: at most kCrossingGrid cells a side, kCrossingTriangles in all
    // (the aeroplane at 256² held 2.9 M triangles, 608 MB), then made coarser while the hash's
    // pairs exceed kCrossingPairs (patches lying on each other put every triangle in a few cells).
    grid = std::min({askedGrid, kCrossingGrid, std::max(kMinCrossingGrid, static_cast<int>(std::sqrt(double(kCrossingTriangles) / (2.0 * std::max(1, P)))))});
    startMeshes();
  }

  void startMeshes() {
    meshes = Meshes{};
    meshes.grids.resize(size_t(P));
    meshes.tris.reserve(static_cast<size_t>(P) * 2 * grid * grid);
    stage = Stage::Mesh, next = 0;
  }

  // A block of triangles a step: about a millisecond natively for the pairs.
  static constexpr int kBlock = 4096;

  bool step() {
    switch (stage) {
      case Stage::Mesh:
        if (next < P) addMesh(meshes, solved, next++, grid, tol);
        if (next == P) {
          hash = Hash{};
          hash.h = std::max(2.0 * meshes.edgeSum / std::max<size_t>(1, meshes.tris.size()), 1e-12 * size);
          stage = Stage::Hash, next = 0;
        }
        return false;
      case Stage::Hash: {
        const int n = static_cast<int>(meshes.tris.size()), to = std::min(n, next + kBlock);
        for (; next < to; ++next) hashTriangle(hash, meshes, next);
        if (next < n) return false;
        for (const auto& [key, b] : hash.buckets) hash.pairs += double(b.size()) * (double(b.size()) - 1) / 2;
        if (hash.pairs > double(kCrossingPairs)) {
          if (grid <= kMinCrossingGrid)
            throw Error(ErrorCode::TooLarge, "the crossing test would compare " + numberText(hash.pairs) + " triangle pairs on a " + std::to_string(grid) + "x" +
                                                 std::to_string(grid) + " mesh per patch, over the limit " + numberText(double(kCrossingPairs)) +
                                                 ": patches lie on one another (" + densestPair(meshes, hash, solved) + ")");
          // Pairs grow as the grid's square: a grid that should bring them under the limit.
          grid = std::max(kMinCrossingGrid, std::min(grid - 1, static_cast<int>(0.9 * grid * std::sqrt(double(kCrossingPairs) / hash.pairs))));
          startMeshes();
          return false;
        }
        stamp.assign(meshes.tris.size(), -1);
        stage = Stage::Pairs, next = 0;
        return false;
      }
      case Stage::Pairs: {
        const int n = static_cast<int>(meshes.tris.size()), to = std::min(n, next + kBlock);
        for (; next < to; ++next) pairsOf(next);
        if (next < n) return false;
        stage = Stage::Done;
        return true;
      }
      case Stage::Done: return true;
    }
    return true;
  }

  // Whether triangle t of patch p lies in the cell row along a join with patch q (a pair
  // may share several joins: both ends of a blend on one surface).
  bool skipped(const Tri& t, int q) const {
    const Patch& pp = *solved[t.patch].patch;
    const Patch& qq = *solved[q].patch;
    if (qq.kind == PatchKind::Primary)
      for (const Meets& m : qq.meets)
        if (m.patch == pp.name && (m.alongU ? t.j : t.i) == (m.end ? grid - 1 : 0)) return true;
    if (pp.kind == PatchKind::Primary)
      for (const Meets& m : pp.meets)
        if (m.patch == qq.name && t.i == (m.atT1 ? grid - 1 : 0)) return true;
    return false;
  }

  void record(const Tri& x, const Tri& y) {
    const Tri& a = solved[x.patch].patch->kind == PatchKind::Primary ? y : x;  // name the blend first
    const Tri& b = &a == &x ? y : x;
    const PatchGrid &ga = meshes.grids[a.patch], &gb = meshes.grids[b.patch];
    auto range = [&](double lo, double hi, int cell) {
      return std::array<double, 2>{lo + (hi - lo) * cell / grid, lo + (hi - lo) * (cell + 1) / grid};
    };
    auto grow = [](std::array<double, 2>& r, const std::array<double, 2>& s) { r[0] = std::min(r[0], s[0]), r[1] = std::max(r[1], s[1]); };
    const auto [at, fresh] = foundAt.try_emplace(int64_t(a.patch) * P + b.patch, found.size());
    if (!fresh) {
      Crossing& c = found[at->second];
      grow(c.u, range(ga.u0, ga.u1, a.i)), grow(c.v, range(ga.v0, ga.v1, a.j));
      grow(c.otherU, range(gb.u0, gb.u1, b.i)), grow(c.otherV, range(gb.v0, gb.v1, b.j));
      ++c.triangles;
      return;
    }
    found.push_back({ga.patch->name, gb.patch->name, range(ga.u0, ga.u1, a.i), range(ga.v0, ga.v1, a.j), range(gb.u0, gb.u1, b.i),
                     range(gb.v0, gb.v1, b.j), 1});
  }

  // Triangle k against the later triangles in its hash cells.
  void pairsOf(int k) {
    const std::vector<Tri>& tris = meshes.tris;
    const Tri& t = tris[k];
    const bool primaryK = solved[t.patch].patch->kind == PatchKind::Primary;
    for (int x = hash.cellOf(t.lo.x()); x <= hash.cellOf(t.hi.x()); ++x)
      for (int y = hash.cellOf(t.lo.y()); y <= hash.cellOf(t.hi.y()); ++y)
        for (int z = hash.cellOf(t.lo.z()); z <= hash.cellOf(t.hi.z()); ++z) {
          auto it = hash.buckets.find(Hash::key(x, y, z));
          if (it == hash.buckets.end()) continue;
          for (int o : it->second) {
            if (o <= k || stamp[o] == k) continue;
            stamp[o] = k;
            const Tri& u = tris[o];
            if (primaryK && solved[u.patch].patch->kind == PatchKind::Primary) continue;  // only blends are certified
            if (((t.lo - u.hi).array() > 0).any() || ((u.lo - t.hi).array() > 0).any()) continue;
            if (t.patch == u.patch) {
              const PatchGrid& g = meshes.grids[t.patch];
              if (cellDistance(t.i, u.i, grid, g.closedU) <= 1 && cellDistance(t.j, u.j, grid, g.closedV) <= 1) continue;
            } else if (skipped(t, u.patch) || skipped(u, t.patch)) {
              continue;
            }
            if (sharePoint(t, u, tol)) {
              // Two patches on one another (not along a join): they coincide, a crossing of area.
              if (t.patch != u.patch && sameTriangle(t, u, tol)) record(t, u);
              continue;
            }
            if (t.patch != u.patch && tangentialContact(t, u, grid)) continue;
            if (trianglesCross(t, u, 1e-9)) record(t, u);
          }
        }
  }
};

CrossingSearch::CrossingSearch(const std::vector<SolvedPatch>& solved, double sceneSize, int grid)
    : state_(std::make_unique<State>(solved, sceneSize, grid)) {}
CrossingSearch::~CrossingSearch() = default;
bool CrossingSearch::step() { return state_->step(); }
const std::vector<Crossing>& CrossingSearch::found() const { return state_->found; }

std::vector<Crossing> findCrossings(const std::vector<SolvedPatch>& solved, double size, int grid) {
  CrossingSearch search(solved, size, grid);
  while (!search.step()) {
  }
  return search.found();
}

}  // namespace pdesurf
