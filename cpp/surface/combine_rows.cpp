#include "surface/combine_rows.hpp"

#include "common/vector_clones.hpp"

namespace pdesurf {

namespace {

// One term's contribution: out[q][i] (+)= G^(a_q)(u_i) · g^(b_q)(v_j) for the Q quantities
// at once, so each G derivative is read once; the first term assigns (no zero fill). G points
// at the piece's first point of G; G', G'' follow `stride` apart.
template <int Q, bool First>
PDESURF_INLINE void addTerm(const std::array<double*, 6>& outRows, const double* G, size_t stride, const double* gv, size_t len) {
  double* __restrict out[Q];
  const double* __restrict Gq[Q];
  double g[Q];
  for (int q = 0; q < Q; ++q)
    out[q] = outRows[q], Gq[q] = G + kRowDerivative[q][0] * stride, g[q] = gv[kRowDerivative[q][1]];
#pragma omp simd
  for (size_t i = 0; i < len; ++i)
    for (int q = 0; q < Q; ++q) {
      if constexpr (First)
        out[q][i] = Gq[q][i] * g[q];
      else
        out[q][i] += Gq[q][i] * g[q];
    }
}

PDESURF_INLINE void combinePiece(const Tabulation& t, int j, size_t i0, size_t len, GridRow& row) {
  const int D = t.depth, Q = row.quantities;
  const size_t m = static_cast<size_t>(t.nu) + 1;
  for (int c = 0; c < 3; ++c) {
    const int T = t.terms[c];
    std::array<double*, 6> out{};
    for (int q = 0; q < Q; ++q) out[q] = row.d[q][c].data();
    if (T == 0)
      for (int q = 0; q < Q; ++q) std::fill(out[q], out[q] + len, 0.0);
    const double* gv = t.vTab[c].data() + static_cast<size_t>(j) * D * T;
    for (int k = 0; k < T; ++k) {
      const double* G = t.uTab[c].data() + static_cast<size_t>(D * k) * m + i0;
      if (Q == 6)
        k == 0 ? addTerm<6, true>(out, G, m, gv + D * k, len) : addTerm<6, false>(out, G, m, gv + D * k, len);
      else
        k == 0 ? addTerm<3, true>(out, G, m, gv + D * k, len) : addTerm<3, false>(out, G, m, gv + D * k, len);
    }
  }
}

#ifdef PDESURF_AVX2_COPY
PDESURF_AVX2 void combinePieceAvx2(const Tabulation& t, int j, size_t i0, size_t len, GridRow& row) { combinePiece(t, j, i0, len, row); }
#endif

}  // namespace

void combineSeparablePiece(const Tabulation& t, int j, size_t i0, size_t len, GridRow& row) {
#ifdef PDESURF_AVX2_COPY
  if (wideVectors()) return combinePieceAvx2(t, j, i0, len, row);
#endif
  combinePiece(t, j, i0, len, row);
}

}  // namespace pdesurf
