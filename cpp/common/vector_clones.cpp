#include "common/vector_clones.hpp"

#include <algorithm>
#include <atomic>

namespace pdesurf {

namespace {

std::atomic<VectorCopy> widestAsked{VectorCopy::Avx512};

VectorCopy widestOfCpu() {
#ifdef PDESURF_VECTOR_COPIES
  // __builtin_cpu_supports also checks that the OS saves the wider registers.
  static const VectorCopy widest =
      __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq") &&
              __builtin_cpu_supports("avx512bw")
          ? VectorCopy::Avx512
      : __builtin_cpu_supports("avx2") ? VectorCopy::Avx2
                                       : VectorCopy::Baseline;
  return widest;
#else
  return VectorCopy::Baseline;
#endif
}

}  // namespace

VectorCopy vectorCopy() { return std::min(widestOfCpu(), widestAsked.load(std::memory_order_relaxed)); }

std::vector<VectorCopy> availableVectorCopies() {
  std::vector<VectorCopy> copies;
  for (VectorCopy c : {VectorCopy::Baseline, VectorCopy::Avx2, VectorCopy::Avx512})
    if (c <= widestOfCpu()) copies.push_back(c);
  return copies;
}

void limitVectorCopy(VectorCopy widest) { widestAsked.store(widest, std::memory_order_relaxed); }

const char* vectorCopyName(VectorCopy c) {
  switch (c) {
    case VectorCopy::Avx512: return "avx512";
    case VectorCopy::Avx2: return "avx2";
    case VectorCopy::Baseline: break;
  }
#ifdef PDESURF_VECTOR_COPIES
  return "sse2";
#elif defined(__EMSCRIPTEN__)
  return "simd128";  // the cloned loops' files are built with -msimd128
#else
  return "scalar";
#endif
}

}  // namespace pdesurf
