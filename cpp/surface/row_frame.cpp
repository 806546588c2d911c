#include "surface/row_frame.hpp"

#include <algorithm>
#include <cmath>

namespace pdesurf {

namespace {

// Branch-free so the loop vectorises (the core is compiled without errno and FP traps): a
// degenerate point computes with a harmless 1 in place of |X_u × X_v|² and is masked to 0.
// Its flags go to chunks of doubles counted after the loop: an integer counter inside it
// would keep it scalar.
template <bool Curvature>
void frameChunk(const GridRow& row, RowFrame& f, float* P, float* Nf, float* H, float* K, size_t i0, size_t i1) {
  constexpr size_t kChunk = 256;
  double pole[kChunk], flat[kChunk], bad[kChunk];
  constexpr double kFloatMax = 3.4028234663852886e38, kDoubleMax = 1.7976931348623157e308;
  const double *xu = row.at(1, 0), *yu = row.at(1, 1), *zu = row.at(1, 2);
  const double *xv = row.at(2, 0), *yv = row.at(2, 1), *zv = row.at(2, 2);
  const double *xuu = nullptr, *yuu = nullptr, *zuu = nullptr, *xuv = nullptr, *yuv = nullptr, *zuv = nullptr,
               *xvv = nullptr, *yvv = nullptr, *zvv = nullptr;
  if constexpr (Curvature) {
    xuu = row.at(3, 0), yuu = row.at(3, 1), zuu = row.at(3, 2);
    xuv = row.at(4, 0), yuv = row.at(4, 1), zuv = row.at(4, 2);
    xvv = row.at(5, 0), yvv = row.at(5, 1), zvv = row.at(5, 2);
  }
  const double *x = row.at(0, 0), *y = row.at(0, 1), *z = row.at(0, 2);
  for (size_t i = i0; i < i1; ++i) {
    const double nx = yu[i] * zv[i] - zu[i] * yv[i], ny = zu[i] * xv[i] - xu[i] * zv[i], nz = xu[i] * yv[i] - yu[i] * xv[i];
    const double det = nx * nx + ny * ny + nz * nz;  // |X_u × X_v|² = EG − F²
    const double E = xu[i] * xu[i] + yu[i] * yu[i] + zu[i] * zu[i], G = xv[i] * xv[i] + yv[i] * yv[i] + zv[i] * zv[i];
    const bool hasNormal = det > 1e-24 * E * G && det > 0;
    pole[i - i0] = hasNormal ? 0.0 : 1.0;
    // NaN fails every comparison, so it lands here too.
    const bool inRange = std::fabs(x[i]) <= kFloatMax && std::fabs(y[i]) <= kFloatMax && std::fabs(z[i]) <= kFloatMax && det <= kDoubleMax;
    bad[i - i0] = inRange ? 0.0 : 1.0;
    const double inv = 1.0 / std::sqrt(hasNormal ? det : 1.0);
    const double unit = hasNormal ? inv : 0.0;
    P[3 * i] = static_cast<float>(x[i]), P[3 * i + 1] = static_cast<float>(y[i]), P[3 * i + 2] = static_cast<float>(z[i]);
    Nf[3 * i] = static_cast<float>(nx * unit), Nf[3 * i + 1] = static_cast<float>(ny * unit), Nf[3 * i + 2] = static_cast<float>(nz * unit);
    if constexpr (Curvature) {
      // A pole: the cross product vanishes against the larger speed (sin t = 1e-16 at t = π
      // leaves X_v = 1e-16 R, not 0: its curvature would divide rounding by rounding).
      const double big = E > G ? E : G;
      const bool regular = det > 1e-24 * big * big;
      flat[i - i0] = regular ? 0.0 : 1.0;
      const double invDet = regular ? inv * inv : 0.0;
      const double F = xu[i] * xv[i] + yu[i] * yv[i] + zu[i] * zv[i];
      const double L = (xuu[i] * nx + yuu[i] * ny + zuu[i] * nz) * inv;
      const double M = (xuv[i] * nx + yuv[i] * ny + zuv[i] * nz) * inv;
      const double N = (xvv[i] * nx + yvv[i] * ny + zvv[i] * nz) * inv;
      const double k = (L * N - M * M) * invDet;
      const double h = 0.5 * (E * N - 2 * F * M + G * L) * invDet;
      // A near-cusp is clamped to what a float holds instead of written as ±inf.
      H[i] = static_cast<float>(std::min(std::max(h, -3e38), 3e38));
      K[i] = static_cast<float>(std::min(std::max(k, -3e38), 3e38));
    }
  }
  for (size_t i = i0; i < i1; ++i) f.poles += pole[i - i0] != 0.0;
  for (size_t i = i0; i < i1 && f.outOfRange < 0; ++i)
    if (bad[i - i0] != 0.0) f.outOfRange = static_cast<long>(i);
  if constexpr (Curvature)
    for (size_t i = i0; i < i1; ++i) f.degenerate += flat[i - i0] != 0.0;
}

}  // namespace

void frameRow(const GridRow& row, float* P, float* N, RowFrame& f, float* H, float* K) {
  const size_t m = row.d[0][0].size();
  f.poles = f.degenerate = 0;
  f.outOfRange = -1;
  const bool curvature = H && K && row.quantities == 6;
  for (size_t i0 = 0; i0 < m; i0 += 256) {
    const size_t i1 = std::min(m, i0 + 256);
    if (curvature)
      frameChunk<true>(row, f, P, N, H, K, i0, i1);
    else
      frameChunk<false>(row, f, P, N, H, K, i0, i1);
  }
}

}  // namespace pdesurf
