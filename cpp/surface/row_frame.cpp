#include "surface/row_frame.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "common/vector_clones.hpp"
#include "surface/float_output.hpp"

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

// X_u × X_v, |X_u × X_v|² = EG − F², E = |X_u|² and G = |X_v|² of one point.
struct Cross {
  double nx, ny, nz, det, E, G;
};
PDESURF_INLINE Cross crossOf(double xu, double yu, double zu, double xv, double yv, double zv) {
  const double nx = yu * zv - zu * yv, ny = zu * xv - xu * zv, nz = xu * yv - yu * xv;
  return {nx, ny, nz, nx * nx + ny * ny + nz * nz, xu * xu + yu * yu + zu * zu, xv * xv + yv * yv + zv * zv};
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
    const auto [nx, ny, nz, det, E, G] = crossOf(xu[k], yu[k], zu[k], xv[k], yv[k], zv[k]);
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

// frameChunk without curvature for points read as two-term components (TwoTerms): the row
// arrays are neither written nor read again. The components are taken in a cyclic order
// c[0], c[1], c[2] that puts the Twos components of two terms first (a cyclic permutation
// commutes with the cross product), so four instantiations cover every mix of term counts
// without multiplying by zero.
template <int Twos, int Lanes>
PDESURF_INLINE bool frameTwoTermsChunk(const TwoTerms (&s)[3], const int (&c)[3], size_t i0, size_t len, float* __restrict P, float* __restrict Nf) {
  alignas(64) double position[3][kChunk], unit[3][kChunk];
  // Local copies (see frameChunk); X and X_v read the same G.
#define PDESURF_TERMS(r)                                                                                  \
  const double *__restrict G1_##r = s[c[r]].G1 + i0, *__restrict G1u_##r = s[c[r]].G1u + i0;              \
  const double *__restrict G2_##r = s[c[r]].G2 + i0, *__restrict G2u_##r = s[c[r]].G2u + i0;              \
  const double g1_##r = s[c[r]].g1, g1v_##r = s[c[r]].g1v, g2_##r = s[c[r]].g2, g2v_##r = s[c[r]].g2v;  \
  double *__restrict position##r = position[c[r]], *__restrict unit##r = unit[c[r]];
  PDESURF_TERMS(0) PDESURF_TERMS(1) PDESURF_TERMS(2)
#undef PDESURF_TERMS
  double flagged = 0;
#pragma omp simd reduction(+ : flagged)
  for (size_t k = 0; k < len; ++k) {
    // a, b, d: components c[0], c[1], c[2] of X, then of X_u and X_v.
    double a = G1_0[k] * g1_0, b = G1_1[k] * g1_1, d = G1_2[k] * g1_2;
    double au = G1u_0[k] * g1_0, bu = G1u_1[k] * g1_1, du = G1u_2[k] * g1_2;
    double av = G1_0[k] * g1v_0, bv = G1_1[k] * g1v_1, dv = G1_2[k] * g1v_2;
    if constexpr (Twos > 0) a += G2_0[k] * g2_0, au += G2u_0[k] * g2_0, av += G2_0[k] * g2v_0;
    if constexpr (Twos > 1) b += G2_1[k] * g2_1, bu += G2u_1[k] * g2_1, bv += G2_1[k] * g2v_1;
    if constexpr (Twos > 2) d += G2_2[k] * g2_2, du += G2u_2[k] * g2_2, dv += G2_2[k] * g2v_2;
    const auto [na, nb, nd, det, E, G] = crossOf(au, bu, du, av, bv, dv);
    const bool hasNormal = det > 1e-24 * E * G;
    const double reach = std::fabs(a) + std::fabs(b) + std::fabs(d) + 0.0 * det;
    flagged += (hasNormal ? 0.0 : 1.0) + (reach <= kFloatMax ? 0.0 : 1.0);
    const double inv = 1.0 / std::sqrt(hasNormal ? det : 1.0);
    position0[k] = a, position1[k] = b, position2[k] = d;
    unit0[k] = na * inv, unit1[k] = nb * inv, unit2[k] = nd * inv;
  }
  if (flagged != 0) return true;
  interleaveBoth<Lanes>(position[0], position[1], position[2], unit[0], unit[1], unit[2], P, Nf, len);
  return false;
}

template <int Lanes>
PDESURF_INLINE bool frameTwoTermsCopy(const TwoTerms (&s)[3], size_t len, float* P, float* N) {
  const bool two[3] = {s[0].terms == 2, s[1].terms == 2, s[2].terms == 2};
  const int twos = two[0] + two[1] + two[2];
  // The cyclic order with the two-term components first: one of them first, or one of one
  // term last.
  int first = 0;
  if (twos == 1) first = two[0] ? 0 : two[1] ? 1 : 2;
  if (twos == 2) first = !two[0] ? 1 : !two[1] ? 2 : 0;
  const int c[3] = {first, (first + 1) % 3, (first + 2) % 3};
  for (size_t i0 = 0; i0 < len; i0 += kChunk) {
    const size_t n = std::min(len - i0, kChunk);
    float *p = P + 3 * i0, *q = N + 3 * i0;
    const bool flagged = twos == 0   ? frameTwoTermsChunk<0, Lanes>(s, c, i0, n, p, q)
                         : twos == 1 ? frameTwoTermsChunk<1, Lanes>(s, c, i0, n, p, q)
                         : twos == 2 ? frameTwoTermsChunk<2, Lanes>(s, c, i0, n, p, q)
                                     : frameTwoTermsChunk<3, Lanes>(s, c, i0, n, p, q);
    if (flagged) return false;
  }
  return true;
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
PDESURF_AVX512 bool frameTwoTermsAvx512(const TwoTerms (&s)[3], size_t len, float* P, float* N) { return frameTwoTermsCopy<8>(s, len, P, N); }
PDESURF_AVX2 void frameRowAvx2(const GridRow& row, float* P, float* N, RowFrame& f, float* H, float* K) { frameRowCopy<8>(row, P, N, f, H, K); }
PDESURF_AVX512 void frameRowAvx512(const GridRow& row, float* P, float* N, RowFrame& f, float* H, float* K) { frameRowCopy<8>(row, P, N, f, H, K); }
#endif

}  // namespace

void frameRow(const GridRow& row, float* P, float* N, RowFrame& f, float* H, float* K) {
  PDESURF_DISPATCH(frameRow, row, P, N, f, H, K);
}

bool frameTwoTerms(const TwoTerms (&s)[3], size_t len, float* P, float* N) {
#ifdef PDESURF_VECTOR_COPIES
  // Natively one copy only, for AVX-512's 32 vector registers: GCC's SSE2 and AVX2 copies of
  // this loop spill and run slower than combining (fig4a at 1024²: 5.8 against 4.5 ms, 3.0
  // against 2.9 ms). Elsewhere the plain version runs (in wasm it is faster than combining).
  return vectorCopy() == VectorCopy::Avx512 && frameTwoTermsAvx512(s, len, P, N);
#else
  return frameTwoTermsCopy<4>(s, len, P, N);
#endif
}

}  // namespace pdesurf
