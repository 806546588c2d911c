#include "surface/row_frame.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "common/vector_clones.hpp"

#ifdef __wasm_simd128__
#include <wasm_simd128.h>
#endif

namespace pdesurf {

namespace {

constexpr size_t kChunk = 64;
constexpr double kFloatMax = 3.4028234663852886e38, kDoubleMax = 1.7976931348623157e308;
constexpr unsigned kPole = 1, kOutOfRange = 2, kDegenerate = 4;

// The row's arrays from point i0 on.
struct RowSlice {
  const double *x, *y, *z, *xu, *yu, *zu, *xv, *yv, *zv;
  const double *xuu = nullptr, *yuu = nullptr, *zuu = nullptr, *xuv = nullptr, *yuv = nullptr, *zuv = nullptr,
               *xvv = nullptr, *yvv = nullptr, *zvv = nullptr;
  RowSlice(const GridRow& row, size_t i0, bool curvature)
      : x(row.at(0, 0) + i0), y(row.at(0, 1) + i0), z(row.at(0, 2) + i0), xu(row.at(1, 0) + i0), yu(row.at(1, 1) + i0),
        zu(row.at(1, 2) + i0), xv(row.at(2, 0) + i0), yv(row.at(2, 1) + i0), zv(row.at(2, 2) + i0) {
    if (!curvature) return;
    xuu = row.at(3, 0) + i0, yuu = row.at(3, 1) + i0, zuu = row.at(3, 2) + i0;
    xuv = row.at(4, 0) + i0, yuv = row.at(4, 1) + i0, zuv = row.at(4, 2) + i0;
    xvv = row.at(5, 0) + i0, yvv = row.at(5, 1) + i0, zvv = row.at(5, 2) + i0;
  }
};

// The flags of one point (kPole, kOutOfRange, kDegenerate), recomputed: only for a chunk whose
// vector pass saw one, to count them and find the first out-of-range point.
unsigned pointFlags(const RowSlice& s, size_t k, bool curvature) {
  const double nx = s.yu[k] * s.zv[k] - s.zu[k] * s.yv[k], ny = s.zu[k] * s.xv[k] - s.xu[k] * s.zv[k],
               nz = s.xu[k] * s.yv[k] - s.yu[k] * s.xv[k];
  const double det = nx * nx + ny * ny + nz * nz;
  const double E = s.xu[k] * s.xu[k] + s.yu[k] * s.yu[k] + s.zu[k] * s.zu[k];
  const double G = s.xv[k] * s.xv[k] + s.yv[k] * s.yv[k] + s.zv[k] * s.zv[k];
  const double big = std::max(E, G);
  const bool inRange = std::fabs(s.x[k]) <= kFloatMax && std::fabs(s.y[k]) <= kFloatMax && std::fabs(s.z[k]) <= kFloatMax && det <= kDoubleMax;
  unsigned flags = 0;
  if (!(det > 1e-24 * E * G)) flags |= kPole;
  if (!inRange) flags |= kOutOfRange;
  if (curvature && !(det > 1e-24 * big * big)) flags |= kDegenerate;
  return flags;
}

// A near-cusp's curvature, clamped to what a float holds instead of ±inf (NaN kept). Done in
// the rare pass over a flagged chunk: in the vector pass std::min/max would become wasm's
// NaN-propagating f64x2.min/max, which V8 expands to about eight instructions each.
float clampToFloat(float x) {
  const float low = x < -3e38f ? -3e38f : x;
  return low > 3e38f ? 3e38f : low;
}

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

// One chunk in two passes. The first is arithmetic on doubles only, so it vectorises (the
// core is compiled without errno and FP traps, and with OpenMP's simd pragmas): a degenerate
// point computes with a harmless 1 in place of |X_u × X_v|² and is masked to 0, and the
// chunk's flagged points are summed. Then floats, interleaved xyz.
// Returns whether any point is flagged (a pole, out of range or, with curvature, degenerate
// or with a curvature beyond ±3e38).
template <bool Curvature, int Lanes>
PDESURF_INLINE bool frameChunk(const RowSlice& s, size_t len, float* __restrict P, float* __restrict Nf, float* __restrict H, float* __restrict K) {
  alignas(64) double unitX[kChunk], unitY[kChunk], unitZ[kChunk], mean[Curvature ? kChunk : 1], gauss[Curvature ? kChunk : 1];
  // Local copies: GCC reloads a struct's pointer members inside the loop and gives up.
  const double *__restrict x = s.x, *__restrict y = s.y, *__restrict z = s.z;
  const double *__restrict xu = s.xu, *__restrict yu = s.yu, *__restrict zu = s.zu;
  const double *__restrict xv = s.xv, *__restrict yv = s.yv, *__restrict zv = s.zv;
  const double *__restrict xuu = s.xuu, *__restrict yuu = s.yuu, *__restrict zuu = s.zuu;
  const double *__restrict xuv = s.xuv, *__restrict yuv = s.yuv, *__restrict zuv = s.zuv;
  const double *__restrict xvv = s.xvv, *__restrict yvv = s.yvv, *__restrict zvv = s.zvv;
  // Flagged points are summed as doubles: an integer OR or count would keep GCC scalar.
  double flagged = 0;
#pragma omp simd reduction(+ : flagged)
  for (size_t k = 0; k < len; ++k) {
    const double nx = yu[k] * zv[k] - zu[k] * yv[k], ny = zu[k] * xv[k] - xu[k] * zv[k],
                 nz = xu[k] * yv[k] - yu[k] * xv[k];
    const double det = nx * nx + ny * ny + nz * nz;  // |X_u × X_v|² = EG − F²
    const double E = xu[k] * xu[k] + yu[k] * yu[k] + zu[k] * zu[k];
    const double G = xv[k] * xv[k] + yv[k] * yv[k] + zv[k] * zv[k];
    // E, G ≥ 0, so this also means det > 0; NaN fails it.
    const bool hasNormal = det > 1e-24 * E * G;
    // A superset of the out-of-range points (NaN or ∞ anywhere makes it NaN or ∞; a sum may
    // flag a point that fits): pointFlags decides.
    const double reach = std::fabs(x[k]) + std::fabs(y[k]) + std::fabs(z[k]) + 0.0 * det;
    flagged += (hasNormal ? 0.0 : 1.0) + (reach <= kFloatMax ? 0.0 : 1.0);
    const double inv = 1.0 / std::sqrt(hasNormal ? det : 1.0);
    const double unit = hasNormal ? inv : 0.0;
    unitX[k] = nx * unit, unitY[k] = ny * unit, unitZ[k] = nz * unit;
    if constexpr (Curvature) {
      // A pole: the cross product vanishes against the larger speed (sin t = 1e-16 at t = π
      // leaves X_v = 1e-16 R, not 0: its curvature would divide rounding by rounding).
      const double big = E > G ? E : G;
      const bool regular = det > 1e-24 * big * big;
      flagged += regular ? 0.0 : 1.0;
      const double invDet = regular ? inv * inv : 0.0;
      const double F = xu[k] * xv[k] + yu[k] * yv[k] + zu[k] * zv[k];
      const double L = (xuu[k] * nx + yuu[k] * ny + zuu[k] * nz) * inv;
      const double M = (xuv[k] * nx + yuv[k] * ny + zuv[k] * nz) * inv;
      const double N = (xvv[k] * nx + yvv[k] * ny + zvv[k] * nz) * inv;
      gauss[k] = (L * N - M * M) * invDet;
      mean[k] = 0.5 * (E * N - 2 * F * M + G * L) * invDet;
      // Beyond ±3e38 (or NaN): the chunk is flagged and frameRow clamps it.
      flagged += std::fabs(mean[k]) <= 3e38 && std::fabs(gauss[k]) <= 3e38 ? 0.0 : 1.0;
    }
  }
  interleaveBoth<Lanes>(x, y, z, unitX, unitY, unitZ, P, Nf, len);
  if constexpr (Curvature) toFloats(mean, H, len), toFloats(gauss, K, len);
  return flagged != 0;
}

template <int Lanes>
PDESURF_INLINE void frameRowCopy(const GridRow& row, float* P, float* N, RowFrame& f, float* H, float* K) {
  const size_t m = row.count;
  f.poles = f.degenerate = 0;
  f.outOfRange = -1;
  const bool curvature = H && K && row.quantities == 6;
  for (size_t i0 = 0; i0 < m; i0 += kChunk) {
    const size_t len = std::min(m - i0, kChunk);
    const RowSlice s(row, i0, curvature);
    const bool flagged = curvature ? frameChunk<true, Lanes>(s, len, P + 3 * i0, N + 3 * i0, H + i0, K + i0)
                                     : frameChunk<false, Lanes>(s, len, P + 3 * i0, N + 3 * i0, nullptr, nullptr);
    if (!flagged) continue;
    for (size_t k = 0; k < len; ++k) {  // rare: count and locate
      const unsigned p = pointFlags(s, k, curvature);
      f.poles += (p & kPole) != 0;
      f.degenerate += (p & kDegenerate) != 0;
      if ((p & kOutOfRange) && f.outOfRange < 0) f.outOfRange = static_cast<long>(i0 + k);
      if (curvature) H[i0 + k] = clampToFloat(H[i0 + k]), K[i0 + k] = clampToFloat(K[i0 + k]);
    }
  }
}

void frameRowBaseline(const GridRow& row, float* P, float* N, RowFrame& f, float* H, float* K) { frameRowCopy<4>(row, P, N, f, H, K); }
#ifdef PDESURF_VECTOR_COPIES
PDESURF_AVX2 void frameRowAvx2(const GridRow& row, float* P, float* N, RowFrame& f, float* H, float* K) { frameRowCopy<8>(row, P, N, f, H, K); }
PDESURF_AVX512 void frameRowAvx512(const GridRow& row, float* P, float* N, RowFrame& f, float* H, float* K) { frameRowCopy<8>(row, P, N, f, H, K); }
#endif

}  // namespace

void frameRow(const GridRow& row, float* P, float* N, RowFrame& f, float* H, float* K) {
  PDESURF_DISPATCH(frameRow, row, P, N, f, H, K);
}

}  // namespace pdesurf
