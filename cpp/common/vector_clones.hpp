// Per-vertex loops compiled twice on x86-64 Linux with GCC: for AVX2 (4 doubles per
// instruction) and for the baseline (SSE2), chosen once at load time by the CPU's features.
// Everywhere else (wasm, where simd128 is a build flag; clang; other CPUs) one plain version.
// Helpers a cloned function calls must be inlined into it to gain (GCC inlines a baseline
// function into an AVX2 one, not the reverse).
#pragma once

#if defined(__x86_64__) && defined(__linux__) && defined(__GNUC__) && !defined(__clang__)
#define PDESURF_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define PDESURF_VECTOR_CLONES
#endif

#define PDESURF_INLINE inline __attribute__((always_inline))
