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
#include "surface/tabulation.hpp"

namespace pdesurf {

struct GridRow {
  int quantities = 3;  // 3, or 6 with second derivatives
  std::array<std::array<std::vector<double>, 3>, 6> d;
  const double* at(int q, int c) const { return d[q][c].data(); }
};

// (a, b) = (u-derivative order, v-derivative order) of each quantity q.
constexpr int kRowDerivative[6][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};

// Calls emitRow(j, row) for j = 0..nv. Throws Error(NonFinite) where a non-separable part is
// not finite.
template <class EmitRow>
void combineRows(const Tabulation& t, EmitRow&& emitRow) {
  const int nv = t.nv, D = t.depth;
  const size_t m = static_cast<size_t>(t.nu) + 1;
  GridRow row;
  row.quantities = D >= 3 ? 6 : 3;
  const int Q = row.quantities;
  for (int q = 0; q < Q; ++q)
    for (int c = 0; c < 3; ++c) row.d[q][c].resize(m);
  std::vector<double> rowV(m);  // v of the current row, for the pointwise programs
  std::array<std::vector<double>, 6> part;
  for (auto& p : part) p.resize(m);
  std::array<double*, 6> partOut{part[0].data(), part[1].data(), part[2].data(), part[3].data(), part[4].data(), part[5].data()};
  for (int j = 0; j <= nv; ++j) {
    for (int c = 0; c < 3; ++c) {
      const int T = t.terms[c];
      for (int q = 0; q < Q; ++q) std::fill(row.d[q][c].begin(), row.d[q][c].end(), 0.0);
      const double* gv = t.vTab[c].data() + static_cast<size_t>(j) * D * T;
      for (int k = 0; k < T; ++k) {
        const double* G = t.uTab[c].data() + static_cast<size_t>(D * k) * m;
        for (int q = 0; q < Q; ++q) {
          const double g = gv[D * k + kRowDerivative[q][1]];
          if (g == 0.0) continue;
          const double* Gq = G + kRowDerivative[q][0] * m;
          double* out = row.d[q][c].data();
          for (size_t i = 0; i < m; ++i) out[i] += Gq[i] * g;
        }
      }
    }
    for (int c = 0; c < 3; ++c) {  // rare: surfaces typed as non-separable expressions
      if (!t.pointwiseProgram[c]) continue;
      std::fill(rowV.begin(), rowV.end(), t.v[j]);
      t.pointwiseProgram[c]->runAll(rowV.data(), t.u.data(), m, partOut.data());
      for (size_t i = 0; i < m; ++i) {
        for (int q = 0; q < Q; ++q) {
          double& x = row.d[q][c][i];
          x += part[q][i];
          if (!std::isfinite(x))
            throw Error(ErrorCode::NonFinite, std::string("component ") + "xyz"[c] + ": the surface is not finite at (t, v) = (" +
                                                  std::to_string(t.u[i]) + ", " + std::to_string(t.v[j]) + ")");
        }
      }
    }
    emitRow(j, static_cast<const GridRow&>(row));
  }
}

}  // namespace pdesurf
