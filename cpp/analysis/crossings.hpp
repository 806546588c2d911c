// Crossing test (docs/analysis.md): a PDE or Bézier patch must not pass through itself or any
// other patch away from its joins. Every patch is sampled on a grid×grid mesh; triangle pairs
// near each other (a uniform spatial hash) are tested edge against triangle. Pairs that touch
// by construction are skipped: neighbouring cells of one patch, triangles sharing a vertex
// position (seams, poles, joins on a common grid) and the cell rows along a declared join.
#pragma once
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace pdesurf {

struct Crossing {
  std::string patch, other;  // other == patch: the patch crosses itself
  std::array<double, 2> u{}, v{};  // parameter ranges on `patch` of the crossing triangles
  std::array<double, 2> otherU{}, otherV{};  // and on `other`
  int triangles = 0;  // crossing triangle pairs found
};

// The test's mesh: at most kCrossingGrid cells a side per patch, whatever grid is asked (the
// check's grid bounds the drawing, not this test: at 1181² a 3-patch scene took 1.2 GB and 7 s;
// a crossing that 256² misses is narrower than a 256th of the patch).
constexpr int kCrossingGrid = 256;
// And over the scene: at most kCrossingTriangles triangles (≈ 32 MB; 22 patches get 77²), then
// the grid made coarser (to kMinCrossingGrid) while the spatial hash's candidate pairs exceed
// kCrossingPairs (≈ 1 s natively); past that, Error(TooLarge) naming two patches that lie on
// one another. Patches that coincide (a triangle of one on a triangle of another, away from
// their joins) are reported as crossing.
constexpr size_t kCrossingTriangles = size_t{1} << 18;
constexpr size_t kCrossingPairs = size_t{1} << 27;
constexpr int kMinCrossingGrid = 16;
std::vector<Crossing> findCrossings(const std::vector<SolvedPatch>& solved, double sceneSize, int grid);

// The same search in steps of about a millisecond or less natively (a patch's mesh, a block of
// the hash or of the triangles' pairs), for the page's report, which stops between them when
// an edit comes. `solved` must outlive it. step() throws findCrossings's errors.
class CrossingSearch {
 public:
  CrossingSearch(const std::vector<SolvedPatch>& solved, double sceneSize, int grid);
  ~CrossingSearch();
  bool step();  // true once the search is done: then found() is the result
  const std::vector<Crossing>& found() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace pdesurf
