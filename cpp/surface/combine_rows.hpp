// Combining tabulated factors into grid rows (internal to surface/ and analysis/): one grid
// row (fixed v_j) at a time, structure-of-arrays, so the inner loops are contiguous
// multiply-adds over u. A row holds X, X_u, X_v and, when the tabulation has depth 3, X_uu,
// X_uv, X_vv: row.d[q][c][i] for quantity q (in that order), component c, grid index i.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/text.hpp"
#include "surface/tabulation.hpp"

namespace pdesurf {

struct GridRow {
  int quantities = 3;  // 3, or 6 with second derivatives
  size_t count = 0;    // points held (the arrays may be longer)
  std::array<std::array<std::vector<double>, 3>, 6> d;
  const double* at(int q, int c) const { return d[q][c].data(); }
};

// (a, b) = (u-derivative order, v-derivative order) of each quantity q.
constexpr int kRowDerivative[6][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};

// The separable part of row j's points i0 .. i0 + len − 1 (surface/combine_rows.cpp):
// row.d[q][c][i] = Σ_t G_t^(a_q)(u_{i0+i}) g_t^(b_q)(v_j) for every quantity q and component c.
void combineSeparablePiece(const Tabulation& t, int j, size_t i0, size_t len, GridRow& row);

// One component of at most two terms over a piece, for reading without combining:
//   X = G1·g1 + G2·g2,  X_u = G1u·g1 + G2u·g2,  X_v = G1·g1v + G2·g2v
// (G1, G1u, G2, G2u from the piece's first point). One term: G2 = G1, G2u = G1u, g2 = g2v
// = 0; none: every scale 0.
struct TwoTerms {
  int terms;  // 0, 1 or 2
  const double *G1, *G1u, *G2, *G2u;
  double g1, g1v, g2, g2v;
};

// The largest term count of t's components when t can be read as TwoTerms (depth 2, no
// pointwise part, at most two terms each), else 3.
int readableTerms(const Tabulation& t);

// Row j's components from point i0 on as TwoTerms; readableTerms(t) ≤ 2 required.
void twoTerms(const Tabulation& t, int j, size_t i0, TwoTerms (&out)[3]);

// Calls emit(j, i0, row) for every row j = 0..nv in pieces of at most `piece` points,
// i0 = 0, piece, 2·piece, …; row holds points i0 .. i0 + row.count − 1. A piece that fits in
// L1 (tessellation uses 256 points) is combined and consumed while it is still there.
// Throws Error(NonFinite) where a non-separable part is not finite.
template <class Emit>
void combineRowPieces(const Tabulation& t, size_t piece, Emit&& emit) {
  const int nv = t.nv, D = t.depth;
  const size_t m = static_cast<size_t>(t.nu) + 1;
  piece = std::min(piece, m);
  GridRow row;
  row.quantities = D >= 3 ? 6 : 3;
  const int Q = row.quantities;
  for (int q = 0; q < Q; ++q)
    for (int c = 0; c < 3; ++c) row.d[q][c].resize(piece);
  const bool pointwise = t.pointwiseProgram[0] || t.pointwiseProgram[1] || t.pointwiseProgram[2];
  std::vector<double> pieceV;  // v of the current row, for the pointwise programs
  std::array<std::vector<double>, 6> part;
  std::array<double*, 6> partOut{};
  if (pointwise) {
    pieceV.resize(piece);
    for (int q = 0; q < 6; ++q) part[q].resize(piece), partOut[q] = part[q].data();
  }
  for (int j = 0; j <= nv; ++j)
    for (size_t i0 = 0; i0 < m; i0 += piece) {
      const size_t len = std::min(piece, m - i0);
      row.count = len;
      combineSeparablePiece(t, j, i0, len, row);
      for (int c = 0; c < 3; ++c) {  // rare: surfaces typed as non-separable expressions
        if (!t.pointwiseProgram[c]) continue;
        std::fill(pieceV.begin(), pieceV.begin() + len, t.v[j]);
        t.pointwiseProgram[c]->runAll(pieceV.data(), t.u.data() + i0, len, partOut.data());
        for (size_t i = 0; i < len; ++i)
          for (int q = 0; q < Q; ++q) {
            double& x = row.d[q][c][i];
            x += part[q][i];
            if (!std::isfinite(x))
              throw Error(ErrorCode::NonFinite, std::string("component ") + "xyz"[c] + ": the surface is not finite at (t, v) = (" +
                                                    numberText(t.u[i0 + i]) + ", " + numberText(t.v[j]) + ")");
          }
      }
      emit(j, i0, static_cast<const GridRow&>(row));
    }
}

// Calls emitRow(j, row) for j = 0..nv with whole rows (row.count = nu + 1).
template <class EmitRow>
void combineRows(const Tabulation& t, EmitRow&& emitRow) {
  combineRowPieces(t, static_cast<size_t>(t.nu) + 1, [&](int j, size_t, const GridRow& row) { emitRow(j, row); });
}

}  // namespace pdesurf
