#include "surface/mesh.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "surface/combine_rows.hpp"
#include "surface/curvature.hpp"

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
        g.X[3 * idx + c] = row.d[0][c][i];
        g.Xu[3 * idx + c] = row.d[1][c][i];
        g.Xv[3 * idx + c] = row.d[2][c][i];
      }
    }
  });
  return g;
}

namespace {

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
      out[0] = a, out[1] = b, out[2] = d, out[3] = b, out[4] = c, out[5] = d;
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
  combineRows(t, [&](int j, const GridRow& row) {
    const double *x = row.at(0, 0), *y = row.at(0, 1), *z = row.at(0, 2);
    const double *xu = row.at(1, 0), *yu = row.at(1, 1), *zu = row.at(1, 2);
    const double *xv = row.at(2, 0), *yv = row.at(2, 1), *zv = row.at(2, 2);
    float* p = pos + 3 * j * w;
    float* q = nrm + 3 * j * w;
    bool pole = false;
    for (size_t i = 0; i < w; ++i) {
      const double nx = yu[i] * zv[i] - zu[i] * yv[i];
      const double ny = zu[i] * xv[i] - xu[i] * zv[i];
      const double nz = xu[i] * yv[i] - yu[i] * xv[i];
      const double len2 = nx * nx + ny * ny + nz * nz;
      const double scale2 = (xu[i] * xu[i] + yu[i] * yu[i] + zu[i] * zu[i]) * (xv[i] * xv[i] + yv[i] * yv[i] + zv[i] * zv[i]);
      const bool regular = len2 > 1e-24 * scale2 && len2 > 0;
      pole |= !regular;
      const double inv = regular ? 1.0 / std::sqrt(len2) : 0.0;
      p[3 * i] = static_cast<float>(x[i]), p[3 * i + 1] = static_cast<float>(y[i]), p[3 * i + 2] = static_cast<float>(z[i]);
      q[3 * i] = static_cast<float>(nx * inv), q[3 * i + 1] = static_cast<float>(ny * inv), q[3 * i + 2] = static_cast<float>(nz * inv);
    }
    if (curvature) m.degenerateVertices += curvatureRow(row, m.meanCurvature.data() + j * w, m.gaussCurvature.data() + j * w);
    if (pole)  // rare: find the pole vertices of this row again
      for (size_t i = 0; i < w; ++i)
        if (q[3 * i] == 0 && q[3 * i + 1] == 0 && q[3 * i + 2] == 0) poles.push_back(j * w + i);
  });
  repairPoleNormals(poles, nu, nv, m);
}

Mesh tessellate(const SeparableSurface& s, int nu, int nv, bool curvature) {
  Mesh m;
  tessellateInto(s, nu, nv, m, curvature);
  return m;
}

}  // namespace pdesurf
