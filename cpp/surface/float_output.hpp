// Doubles out as floats, xyz interleaved, for the per-vertex loops (internal to surface/):
// helpers inlined into each vector copy (common/vector_clones.hpp).
#pragma once
#include <cstddef>
#include <cstring>

#include "common/vector_clones.hpp"

#ifdef __wasm_simd128__
#include <wasm_simd128.h>
#endif

namespace pdesurf {

typedef float Float4 __attribute__((vector_size(16)));

// Four doubles from p as floats. In wasm, LLVM 14 turns a vectorised double → float
// conversion into extract, demote and store per lane; f32x4.demote_f64x2_zero is said outright.
// Natively one 4-wide conversion (one vcvtpd2ps with AVX2): GCC turns two 2-wide ones into
// two converts of zero-extended halves plus moves.
PDESURF_INLINE Float4 toFloat4(const double* p) {
#ifdef __wasm_simd128__
  const v128_t low = wasm_f32x4_demote_f64x2_zero(wasm_v128_load(p)), high = wasm_f32x4_demote_f64x2_zero(wasm_v128_load(p + 2));
  return reinterpret_cast<Float4>(wasm_i64x2_shuffle(low, high, 0, 2));
#else
  typedef double Double4 __attribute__((vector_size(32)));
  Double4 v;
  std::memcpy(&v, p, 32);
  return __builtin_convertvector(v, Float4);
#endif
}

// out[0..11] = (a[k], b[k], c[k]) as floats for k = 0..3, in six vector shuffles (neither GCC
// nor clang vectorises a stride-3 store from separate arrays by itself). Generic vectors: SSE
// natively, simd128 in wasm, scalar code without either.
PDESURF_INLINE void interleave4(const double* a, const double* b, const double* c, float* out) {
  const Float4 x = toFloat4(a), y = toFloat4(b), z = toFloat4(c);
  // Each shuffle takes two lanes from either source: one shufps (SSE) or i8x16.shuffle
  // that V8 lowers to one.
  const Float4 xyEven = __builtin_shufflevector(x, y, 0, 2, 4, 6);     // x0 x2 y0 y2
  const Float4 yzOdd = __builtin_shufflevector(y, z, 1, 3, 5, 7);      // y1 y3 z1 z3
  const Float4 zEvenXOdd = __builtin_shufflevector(z, x, 0, 2, 5, 7);  // z0 z2 x1 x3
  const Float4 o0 = __builtin_shufflevector(xyEven, zEvenXOdd, 0, 2, 4, 6);  // x0 y0 z0 x1
  const Float4 o1 = __builtin_shufflevector(yzOdd, xyEven, 0, 2, 5, 7);      // y1 z1 x2 y2
  const Float4 o2 = __builtin_shufflevector(zEvenXOdd, yzOdd, 1, 3, 5, 7);   // z2 x3 y3 z3
  std::memcpy(out, &o0, 16), std::memcpy(out + 4, &o1, 16), std::memcpy(out + 8, &o2, 16);
}

typedef float Float8 __attribute__((vector_size(32)));

// The same for eight points with 256-bit vectors (the AVX2 and AVX-512 copies): shufps works
// within each 128-bit half, so the six shuffles interleave points 0-3 and 4-7 at once, and
// three cross-half permutes put the outputs in order.
PDESURF_INLINE void interleave8(const double* a, const double* b, const double* c, float* out) {
  typedef double Double8 __attribute__((vector_size(64)));
  Double8 da, db, dc;
  std::memcpy(&da, a, 64), std::memcpy(&db, b, 64), std::memcpy(&dc, c, 64);
  const Float8 x = __builtin_convertvector(da, Float8), y = __builtin_convertvector(db, Float8), z = __builtin_convertvector(dc, Float8);
  const Float8 xyEven = __builtin_shufflevector(x, y, 0, 2, 8, 10, 4, 6, 12, 14);
  const Float8 yzOdd = __builtin_shufflevector(y, z, 1, 3, 9, 11, 5, 7, 13, 15);
  const Float8 zEvenXOdd = __builtin_shufflevector(z, x, 0, 2, 9, 11, 4, 6, 13, 15);
  const Float8 o0 = __builtin_shufflevector(xyEven, zEvenXOdd, 0, 2, 8, 10, 4, 6, 12, 14);
  const Float8 o1 = __builtin_shufflevector(yzOdd, xyEven, 0, 2, 9, 11, 4, 6, 13, 15);
  const Float8 o2 = __builtin_shufflevector(zEvenXOdd, yzOdd, 1, 3, 9, 11, 5, 7, 13, 15);
  const Float8 w0 = __builtin_shufflevector(o0, o1, 0, 1, 2, 3, 8, 9, 10, 11);
  const Float8 w1 = __builtin_shufflevector(o2, o0, 0, 1, 2, 3, 12, 13, 14, 15);
  const Float8 w2 = __builtin_shufflevector(o1, o2, 4, 5, 6, 7, 12, 13, 14, 15);
  std::memcpy(out, &w0, 32), std::memcpy(out + 8, &w1, 32), std::memcpy(out + 16, &w2, 32);
}

// P[3k..3k+2] = (x[k], y[k], z[k]) and N[3k..3k+2] = (nx[k], ny[k], nz[k]) as floats, the two
// written side by side: two output streams advancing together take about half the time of
// one written after the other in pieces (24 MB at 1024², measured on an EPYC VM).
template <int Lanes>
PDESURF_INLINE void interleaveBoth(const double* __restrict x, const double* __restrict y, const double* __restrict z,
                                   const double* __restrict nx, const double* __restrict ny, const double* __restrict nz,
                                   float* __restrict P, float* __restrict N, size_t n) {
  size_t k = 0;
  if constexpr (Lanes == 8)
    for (; k + 8 <= n; k += 8) interleave8(x + k, y + k, z + k, P + 3 * k), interleave8(nx + k, ny + k, nz + k, N + 3 * k);
  for (; k + 4 <= n; k += 4) interleave4(x + k, y + k, z + k, P + 3 * k), interleave4(nx + k, ny + k, nz + k, N + 3 * k);
  for (; k < n; ++k) {
    P[3 * k] = static_cast<float>(x[k]), P[3 * k + 1] = static_cast<float>(y[k]), P[3 * k + 2] = static_cast<float>(z[k]);
    N[3 * k] = static_cast<float>(nx[k]), N[3 * k + 1] = static_cast<float>(ny[k]), N[3 * k + 2] = static_cast<float>(nz[k]);
  }
}

// out[k] = a[k] as a float.
PDESURF_INLINE void toFloats(const double* __restrict a, float* __restrict out, size_t n) {
  size_t k = 0;
  for (; k + 4 <= n; k += 4) {
    const Float4 x = toFloat4(a + k);
    std::memcpy(out + k, &x, 16);
  }
  for (; k < n; ++k) out[k] = static_cast<float>(a[k]);
}

}  // namespace pdesurf
