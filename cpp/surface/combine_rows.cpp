#include "surface/combine_rows.hpp"

#include "common/vector_clones.hpp"

namespace pdesurf {

namespace {

// Terms k and, with Two, k + 1: out[q][i] (+)= Σ G^(a_q)(u_i) · g^(b_q)(v_j) for the Q
// quantities at once, so each G derivative is read once and each output is written once per
// two terms (the pass is bound by its stores); the first pass assigns (no zero fill). G
// points at the piece's first point of term k's G; G', G'' follow `stride` apart, and term
// k + 1's G `depth · stride` after term k's.
template <int Q, bool First, bool Two>
PDESURF_INLINE void addTerms(const std::array<double*, 6>& outRows, const double* G, size_t stride, int depth, const double* gv, size_t len) {
  double* __restrict out[Q];
  const double *__restrict Gq[Q], *__restrict Hq[Q];
  double g[Q], h[Q];
  for (int q = 0; q < Q; ++q) {
    out[q] = outRows[q], Gq[q] = G + kRowDerivative[q][0] * stride, g[q] = gv[kRowDerivative[q][1]];
    Hq[q] = Gq[q] + (Two ? depth * stride : 0), h[q] = Two ? gv[depth + kRowDerivative[q][1]] : 0.0;
  }
#pragma omp simd
  for (size_t i = 0; i < len; ++i)
    for (int q = 0; q < Q; ++q) {
      double sum = Gq[q][i] * g[q];
      if constexpr (Two) sum += Hq[q][i] * h[q];
      if constexpr (First)
        out[q][i] = sum;
      else
        out[q][i] += sum;
    }
}

template <int Q>
PDESURF_INLINE void addAllTerms(const std::array<double*, 6>& out, const double* uTab, size_t m, int D, int T, const double* gv, size_t len) {
  for (int k = 0; k < T; k += 2) {
    const double* G = uTab + static_cast<size_t>(D * k) * m;
    const bool first = k == 0, two = k + 1 < T;
    if (first)
      two ? addTerms<Q, true, true>(out, G, m, D, gv + D * k, len) : addTerms<Q, true, false>(out, G, m, D, gv + D * k, len);
    else
      two ? addTerms<Q, false, true>(out, G, m, D, gv + D * k, len) : addTerms<Q, false, false>(out, G, m, D, gv + D * k, len);
  }
}

PDESURF_INLINE void combinePiece(const Tabulation& t, int j, size_t i0, size_t len, GridRow& row) {
  const int D = t.depth, Q = row.quantities;
  const size_t m = static_cast<size_t>(t.nu) + 1;
  for (int c = 0; c < 3; ++c) {
    const int T = t.terms[c];
    std::array<double*, 6> out{};
    for (int q = 0; q < Q; ++q) out[q] = row.d[q][c].data();
    if (T == 0) {  // (its tables are empty: no pointer into them)
      for (int q = 0; q < Q; ++q) std::fill(out[q], out[q] + len, 0.0);
      continue;
    }
    const double* gv = t.vTab[c].data() + static_cast<size_t>(j) * D * T;
    if (Q == 6)
      addAllTerms<6>(out, t.uTab[c].data() + i0, m, D, T, gv, len);
    else
      addAllTerms<3>(out, t.uTab[c].data() + i0, m, D, T, gv, len);
  }
}

void combinePieceBaseline(const Tabulation& t, int j, size_t i0, size_t len, GridRow& row) { combinePiece(t, j, i0, len, row); }
#ifdef PDESURF_VECTOR_COPIES
PDESURF_AVX2 void combinePieceAvx2(const Tabulation& t, int j, size_t i0, size_t len, GridRow& row) { combinePiece(t, j, i0, len, row); }
PDESURF_AVX512 void combinePieceAvx512(const Tabulation& t, int j, size_t i0, size_t len, GridRow& row) { combinePiece(t, j, i0, len, row); }
#endif

}  // namespace

int readableTerms(const Tabulation& t) {
  int most = 0;
  for (int c = 0; c < 3; ++c) {
    if (t.pointwiseProgram[c]) return 3;
    most = std::max(most, t.terms[c]);
  }
  return t.depth == 2 ? std::min(most, 3) : 3;
}

void twoTerms(const Tabulation& t, int j, size_t i0, TwoTerms (&out)[3]) {
  const size_t m = static_cast<size_t>(t.nu) + 1;
  for (int c = 0; c < 3; ++c) {
    const int T = t.terms[c];
    const double* gv = t.vTab[c].data() + static_cast<size_t>(j) * 2 * T;  // g, g' per term
    // No term: any finite array (the grid's u), scaled by 0.
    const double* G1 = T > 0 ? t.uTab[c].data() + i0 : t.u.data() + i0;
    const double* G1u = T > 0 ? G1 + m : G1;
    const double* G2 = T > 1 ? G1 + 2 * m : G1;
    const double* G2u = T > 1 ? G1 + 3 * m : G1u;
    out[c] = {T, G1, G1u, G2, G2u, T > 0 ? gv[0] : 0.0, T > 0 ? gv[1] : 0.0, T > 1 ? gv[2] : 0.0, T > 1 ? gv[3] : 0.0};
  }
}

void combineSeparablePiece(const Tabulation& t, int j, size_t i0, size_t len, GridRow& row) {
  PDESURF_DISPATCH(combinePiece, t, j, i0, len, row);
}

}  // namespace pdesurf
