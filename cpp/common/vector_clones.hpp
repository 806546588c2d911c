// Per-vertex loops compiled twice on x86-64 Linux with GCC: for AVX2 (4 doubles per
// instruction) and for the baseline (SSE2, 2 doubles, as wasm's simd128), the AVX2 copy run
// when the CPU has it. Everywhere else (wasm, where simd128 is a build flag; clang; other
// CPUs) one plain version. A cloned loop is a PDESURF_INLINE body called from two thin
// functions, one marked PDESURF_AVX2; its helpers must be PDESURF_INLINE too, so they are
// compiled into each copy (GCC inlines a baseline function into an AVX2 one, not the reverse).
#pragma once

#if defined(__x86_64__) && defined(__linux__) && defined(__GNUC__) && !defined(__clang__)
#define PDESURF_AVX2_COPY 1
#define PDESURF_AVX2 __attribute__((target("avx2")))
#endif

#define PDESURF_INLINE inline __attribute__((always_inline))

namespace pdesurf {

// Whether the cloned loops run their AVX2 copy: the build has one, the CPU has AVX2 and no
// benchmark asked for the baseline.
bool wideVectors();

// For benchmarks that compare like with like (wasm against the native 128-bit copy): true
// runs the baseline copy, false the widest the CPU has.
void useBaselineVectors(bool baseline);

}  // namespace pdesurf
