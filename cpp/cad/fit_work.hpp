// The work of one CAD export's fit (issue 38 #3), summed over the scene's patches and, in the
// CLI, its threads: each certificate round's points times what a point costs
// (SurfaceOnGrid::pointCost: terms and program instructions), each least-squares round's, and
// each derivative bound's interval-program steps; charged before that work is done. Each
// patch was already bounded alone (spans, grid points, rounds), but 32 heavy patches, or one
// heavy fill whose derivative bounds halve their intervals, took minutes (226 s, 398 s).
#pragma once
#include <atomic>
#include <cstdint>

#include "common/errors.hpp"

namespace pdesurf {

// In multiply-adds (an interval step counts kIntervalStepCost). The aeroplane (22 patches, the
// largest example) needs 2.2e9; the limit is about 4 times that (about 10 s natively).
constexpr double kSceneFitWork = 1e10;
constexpr double kIntervalStepCost = 4;

// The scene's budget, not one patch's: thrown as it is (fitPatch does not prefix the patch,
// whichever thread crossed the limit first).
class SceneWorkExceeded : public Error {
 public:
  explicit SceneWorkExceeded(double limit);
};

class FitWork {
 public:
  explicit FitWork(double limit = kSceneFitWork) : limit_(limit) {}
  // Adds `units` of work about to be done; throws SceneWorkExceeded when the sum passes the limit.
  void charge(double units);
  double used() const { return double(used_.load()); }

 private:
  double limit_;
  std::atomic<uint64_t> used_{0};
};

}  // namespace pdesurf
