#include "common/vector_clones.hpp"

#include <atomic>

namespace pdesurf {

namespace {
std::atomic<bool> baselineAsked{false};
}

bool wideVectors() {
#ifdef PDESURF_AVX2_COPY
  static const bool cpuHasAvx2 = __builtin_cpu_supports("avx2");
  return cpuHasAvx2 && !baselineAsked.load(std::memory_order_relaxed);
#else
  return false;
#endif
}

void useBaselineVectors(bool baseline) { baselineAsked.store(baseline, std::memory_order_relaxed); }

}  // namespace pdesurf
