// Per-vertex loops compiled three times on x86-64 Linux with GCC: for AVX-512 (8 doubles per
// instruction), for AVX2 (4) and for the baseline (SSE2, 2 doubles, as wasm's simd128), the
// widest the CPU has run. Everywhere else (wasm, where simd128 is a build flag; clang; other
// CPUs) one plain version. A cloned loop is a PDESURF_INLINE body called from thin functions
// marked PDESURF_AVX512 and PDESURF_AVX2 and one unmarked; its helpers must be
// PDESURF_INLINE too, so they are compiled into each copy (GCC inlines a baseline function
// into a wider one, not the reverse).
#pragma once

#include <vector>

#if defined(__x86_64__) && defined(__linux__) && defined(__GNUC__) && !defined(__clang__)
#define PDESURF_VECTOR_COPIES 1
#define PDESURF_AVX2 __attribute__((target("avx2")))
// GCC's generic tuning keeps AVX-512 loops 256 bits wide unless asked.
#define PDESURF_AVX512 __attribute__((target("avx512f,avx512vl,avx512dq,avx512bw,prefer-vector-width=512")))
#endif

#define PDESURF_INLINE inline __attribute__((always_inline))

namespace pdesurf {

enum class VectorCopy { Baseline, Avx2, Avx512 };

// The copy the cloned loops run: the widest the build has and the CPU runs, within the
// limit set below.
VectorCopy vectorCopy();

// The copies this build has and this CPU runs, narrowest first.
std::vector<VectorCopy> availableVectorCopies();

// For benchmarks and tests that compare the copies: the widest copy to run.
void limitVectorCopy(VectorCopy widest);

const char* vectorCopyName(VectorCopy c);  // "sse2", "avx2", "avx512"; "simd128" or "scalar" for the plain version

// Calls the copy of a cloned function that vectorCopy() names.
#ifdef PDESURF_VECTOR_COPIES
#define PDESURF_DISPATCH(name, ...)                                   \
  switch (vectorCopy()) {                                             \
    case VectorCopy::Avx512: return name##Avx512(__VA_ARGS__);        \
    case VectorCopy::Avx2: return name##Avx2(__VA_ARGS__);            \
    case VectorCopy::Baseline: break;                                 \
  }                                                                   \
  return name##Baseline(__VA_ARGS__)
#else
#define PDESURF_DISPATCH(name, ...) return name##Baseline(__VA_ARGS__)
#endif

}  // namespace pdesurf
