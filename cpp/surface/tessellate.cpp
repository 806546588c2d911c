#include "surface/mesh.hpp"

#include <algorithm>
#include <cmath>

#include "common/text.hpp"
#include "common/errors.hpp"
#include "surface/combine_rows.hpp"
#include "surface/row_frame.hpp"

namespace pdesurf {

GridSamples sampleGrid(const SeparableSurface& s, int nu, int nv) {
  const Tabulation t = tabulate(s, nu, nv);
  GridSamples g;
  g.nu = nu;
  g.nv = nv;
  g.u = t.u;
  g.v = t.v;
  const size_t n = static_cast<size_t>(nu + 1) * (nv + 1);
  g.X.resize(3 * n);
  g.Xu.resize(3 * n);
  g.Xv.resize(3 * n);
  const size_t m = static_cast<size_t>(nu) + 1;
  combineRows(t, [&](int j, const GridRow& row) {
    for (size_t i = 0; i < m; ++i) {
      const size_t idx = j * m + i;
      for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(row.d[0][c][i]) || !std::isfinite(row.d[1][c][i]) || !std::isfinite(row.d[2][c][i]))
          throw Error(ErrorCode::NonFinite, "the surface at (t, v) = (" + numberText(t.u[i]) + ", " + numberText(t.v[j]) +
                                                ") or its derivatives are not finite");
        g.X[3 * idx + c] = row.d[0][c][i];
        g.Xu[3 * idx + c] = row.d[1][c][i];
        g.Xv[3 * idx + c] = row.d[2][c][i];
      }
    }
  });
  return g;
}

namespace {

[[noreturn]] void outOfRange(const Tabulation& t, size_t i, int j) {
  throw Error(ErrorCode::NonFinite, "the surface at (t, v) = (" + numberText(t.u[i]) + ", " + numberText(t.v[j]) +
                                        ") is beyond what a float holds (|x| > 3.4e38) or not finite");
}

void buildGridData(int nu, int nv, Mesh& m) {
  const size_t n = static_cast<size_t>(nu + 1) * (nv + 1);
  m.uvs.resize(2 * n);
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const size_t idx = static_cast<size_t>(j) * (nu + 1) + i;
      m.uvs[2 * idx] = static_cast<float>(i) / nu;
      m.uvs[2 * idx + 1] = static_cast<float>(j) / nv;
    }
  m.indices.resize(static_cast<size_t>(6) * nu * nv);
  uint32_t* out = m.indices.data();
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const uint32_t a = j * (nu + 1) + i, b = a + (nu + 1), c = b + 1, d = a + 1;
      // Counter-clockwise seen from where X_u × X_v points: each face agrees with its
      // vertex normals (exports, back-face culling and two-sided lighting rely on it).
      out[0] = a, out[1] = d, out[2] = b, out[3] = b, out[4] = d, out[5] = c;
      out += 6;
    }
}

// Poles (X_u × X_v = 0) borrow the normal of a regular vertex a few cells away along u, then
// v; a fully collapsed patch keeps zero normals.
void repairPoleNormals(const std::vector<size_t>& poles, int nu, int nv, Mesh& m) {
  for (size_t idx : poles) {
    const int i = static_cast<int>(idx % (nu + 1)), j = static_cast<int>(idx / (nu + 1));
    bool found = false;
    for (int step = 1; step <= 4 && !found; ++step) {
      const int cand[4][2] = {{i + step, j}, {i - step, j}, {i, j + step}, {i, j - step}};
      for (const auto& c : cand) {
        if (c[0] < 0 || c[0] > nu || c[1] < 0 || c[1] > nv) continue;
        const size_t k = static_cast<size_t>(c[1]) * (nu + 1) + c[0];
        const float* nk = &m.normals[3 * k];
        if (nk[0] == 0 && nk[1] == 0 && nk[2] == 0) continue;
        for (int d = 0; d < 3; ++d) m.normals[3 * idx + d] = nk[d];
        found = true;
        break;
      }
    }
  }
}

}  // namespace

void tessellateInto(const SeparableSurface& s, int nu, int nv, Mesh& m, bool curvature) {
  const Tabulation t = tabulate(s, nu, nv, curvature ? 2 : 1);
  const size_t n = static_cast<size_t>(nu + 1) * (nv + 1);
  if (m.nu != nu || m.nv != nv || m.uvs.size() != 2 * n) buildGridData(nu, nv, m);
  m.nu = nu;
  m.nv = nv;
  m.positions.resize(3 * n);
  m.normals.resize(3 * n);
  float* pos = m.positions.data();
  float* nrm = m.normals.data();
  if (curvature) {
    m.meanCurvature.resize(n);
    m.gaussCurvature.resize(n);
  } else {
    m.meanCurvature.clear();
    m.gaussCurvature.clear();
  }
  m.degenerateVertices = 0;
  std::vector<size_t> poles;
  const size_t w = static_cast<size_t>(nu) + 1;
  RowFrame frame;
  auto frameCombined = [&](int j, size_t i0, const GridRow& row) {
    const size_t first = static_cast<size_t>(j) * w + i0;
    float* q = nrm + 3 * first;
    if (curvature)
      frameRow(row, pos + 3 * first, q, frame, m.meanCurvature.data() + first, m.gaussCurvature.data() + first);
    else
      frameRow(row, pos + 3 * first, q, frame);
    m.degenerateVertices += frame.degenerate;
    if (frame.outOfRange >= 0) outOfRange(t, i0 + frame.outOfRange, j);
    if (frame.poles > 0)  // rare: find the pole vertices of this piece again
      for (size_t i = 0; i < row.count; ++i)
        if (q[3 * i] == 0 && q[3 * i + 1] == 0 && q[3 * i + 2] == 0) poles.push_back(first + i);
  };
  const int terms = readableTerms(t);
  if (curvature || terms > 2) {
    combineRowPieces(t, kFramePiece, frameCombined);
  } else {
    // Components of at most two terms (most blends) are read straight from the tabulation; a
    // piece with a pole or a point out of range is combined and framed as above.
    GridRow row;
    TwoTerms pieceTerms[3];
    for (int j = 0; j <= nv; ++j)
      for (size_t i0 = 0; i0 < w; i0 += kFramePiece) {
        const size_t len = std::min(kFramePiece, w - i0), first = static_cast<size_t>(j) * w + i0;
        twoTerms(t, j, i0, pieceTerms);
        if (frameTwoTerms(pieceTerms, len, pos + 3 * first, nrm + 3 * first)) continue;
        if (row.d[0][0].size() < len)
          for (int q = 0; q < 3; ++q)
            for (int c = 0; c < 3; ++c) row.d[q][c].resize(kFramePiece);
        row.count = len;
        combineSeparablePiece(t, j, i0, len, row);
        frameCombined(j, i0, row);
      }
  }
  repairPoleNormals(poles, nu, nv, m);
}

Mesh tessellate(const SeparableSurface& s, int nu, int nv, bool curvature) {
  Mesh m;
  tessellateInto(s, nu, nv, m, curvature);
  return m;
}

}  // namespace pdesurf
