#include "parallel_fit.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>

namespace pdesurf::cli {

int defaultJobs() {
  const unsigned n = std::thread::hardware_concurrency();
  return int(std::clamp(n, 1u, 8u));
}

namespace {

// A guess of a patch's fit time, to hand the longest out first (a long patch taken last
// would leave the other threads idle): its terms, a pointwise part counting as many.
size_t workGuess(const SolvedPatch& p) {
  if (p.patch->kind == PatchKind::Bezier) return 0;
  size_t n = 0;
  for (int c = 0; c < 3; ++c) n += p.surface.component[size_t(c)].size() + (p.surface.pointwise[size_t(c)] ? 64 : 0);
  return n;
}

}  // namespace

std::vector<PatchFit> fitSceneOnThreads(const std::string& sceneText, const std::vector<SolvedPatch>& solved,
                                        const FitOptions& fit, int jobs) {
  const size_t n = solved.size();
  std::vector<size_t> order(n);
  for (size_t i = 0; i < n; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return workGuess(solved[a]) > workGuess(solved[b]); });
  std::vector<PatchFit> out(n);
  std::vector<std::exception_ptr> failed(n);
  std::atomic<size_t> next{0};
  // The first patch (in the scene's order) that fails so far: a patch after it is not started,
  // one before it still is, so the error rethrown is the one fitScene meets, whatever the timing.
  std::atomic<size_t> firstFailed{n};
  // One budget for the scene, whichever thread fits which patch (cad/fit_work.hpp).
  FitWork budget;
  FitOptions shared = fit;
  if (!shared.work) shared.work = &budget;
  auto work = [&](const std::vector<SolvedPatch>& own) {
    for (size_t k; (k = next.fetch_add(1)) < n;) {
      const size_t i = order[k];
      if (i > firstFailed.load()) continue;
      try {
        out[i] = fitPatch(own[i], shared);
      } catch (...) {
        failed[i] = std::current_exception();
        for (size_t f = firstFailed.load(); i < f && !firstFailed.compare_exchange_weak(f, i);) {
        }
      }
    }
  };
  std::vector<std::thread> threads;
  for (int t = 1; t < std::min<long>(jobs, long(n)); ++t)
    threads.emplace_back([&] {
      try {
        const Scene scene = parseScene(sceneText);
        const std::vector<SolvedPatch> own = solveScene(scene);
        work(own);
      } catch (...) {
        // The scene this thread's caller solved cannot fail here but for memory: the patches are
        // left to the other threads (the calling thread takes every patch left).
      }
    });
  work(solved);
  for (std::thread& t : threads) t.join();
  if (firstFailed.load() < n) std::rethrow_exception(failed[firstFailed.load()]);
  return out;
}

}  // namespace pdesurf::cli
