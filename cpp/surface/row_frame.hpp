// The per-vertex work of tessellation for one grid row, in one pass over its
// structure-of-arrays quantities: float positions, unit normals and, with second derivatives,
// mean and Gaussian curvature (formulas in surface/curvature.hpp).
#pragma once
#include "surface/combine_rows.hpp"

namespace pdesurf {

// Points framed per vector pass; tessellation combines rows in pieces of this size so a
// piece is framed while it is still in L1.
constexpr size_t kFramePiece = 256;

struct RowFrame {
  int poles = 0;       // points where |X_u × X_v|² ≤ 1e-24 E G: normal (0, 0, 0)
  int degenerate = 0;  // points where |X_u × X_v|² ≤ 1e-24 max(E, G)²: no curvature (H = K = 0)
  // The first point whose position is not finite or beyond what a float holds, or whose
  // derivatives overflow (its normal would be NaN); -1 when there is none. The caller throws.
  long outOfRange = -1;
};

// Writes P[3i..3i+2] = X and N[3i..3i+2] = unit normal for the row's points i, and counts in
// f. With H and K (row.quantities == 6 required), also H[i], K[i], clamped to what a float
// holds.
void frameRow(const GridRow& row, float* P, float* N, RowFrame& f, float* H = nullptr, float* K = nullptr);

// frameRow without curvature for a piece of len points read as two-term components
// (twoTerms), without combining the row: most blends.
// Returns false, with P and N partly written, when a point is flagged or when this CPU's copy
// frames faster from combined rows; the caller then combines the piece and calls frameRow,
// which counts and locates.
bool frameTwoTerms(const TwoTerms (&s)[3], size_t len, float* P, float* N);

}  // namespace pdesurf
