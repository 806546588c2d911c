#include "surface/mesh.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "surface/tabulation.hpp"

namespace pdesurf {

namespace {

// Combines the tabulated factors one grid row (fixed v) at a time into structure-of-arrays
// row buffers, then calls emitRow(j, row): row.X[c][i], row.Xu[c][i], row.Xv[c][i].
struct Row {
  std::array<std::vector<double>, 3> X, Xu, Xv;
};

template <class EmitRow>
void combineRows(const Tabulation& t, EmitRow&& emitRow) {
  const int nu = t.nu, nv = t.nv;
  const size_t m = static_cast<size_t>(nu) + 1;
  Row row;
  for (int c = 0; c < 3; ++c) row.X[c].resize(m), row.Xu[c].resize(m), row.Xv[c].resize(m);
  for (int j = 0; j <= nv; ++j) {
    for (int c = 0; c < 3; ++c) {
      const int T = t.terms[c];
      double* x = row.X[c].data();
      double* xu = row.Xu[c].data();
      double* xv = row.Xv[c].data();
      std::fill(x, x + m, 0.0), std::fill(xu, xu + m, 0.0), std::fill(xv, xv + m, 0.0);
      const double* gv = t.vTab[c].data() + static_cast<size_t>(j) * 2 * T;
      for (int k = 0; k < T; ++k) {
        const double g = gv[2 * k], dg = gv[2 * k + 1];
        const double* G = t.uTab[c].data() + static_cast<size_t>(2 * k) * m;
        const double* dG = G + m;
        for (size_t i = 0; i < m; ++i) {
          x[i] += G[i] * g;
          xu[i] += dG[i] * g;
          xv[i] += G[i] * dg;
        }
      }
    }
    for (int c = 0; c < 3; ++c) {  // rare: surfaces typed as non-separable expressions
      const auto& pw = t.pointwise[c];
      if (!pw[0]) continue;
      for (size_t i = 0; i < m; ++i) {
        const double vars[2] = {t.v[j], t.u[i]};
        row.X[c][i] += evaluate(*pw[0], vars);
        row.Xu[c][i] += evaluate(*pw[1], vars);
        row.Xv[c][i] += evaluate(*pw[2], vars);
        if (!std::isfinite(row.X[c][i]) || !std::isfinite(row.Xu[c][i]) || !std::isfinite(row.Xv[c][i]))
          throw Error(ErrorCode::NonFinite, std::string("component ") + "xyz"[c] + ": the surface is not finite at (t, v) = (" +
                                                std::to_string(t.u[i]) + ", " + std::to_string(t.v[j]) + ")");
      }
    }
    emitRow(j, row);
  }
}

}  // namespace

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
  combineRows(t, [&](int j, const Row& row) {
    for (size_t i = 0; i < m; ++i) {
      const size_t idx = j * m + i;
      for (int c = 0; c < 3; ++c) {
        g.X[3 * idx + c] = row.X[c][i];
        g.Xu[3 * idx + c] = row.Xu[c][i];
        g.Xv[3 * idx + c] = row.Xv[c][i];
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

void tessellateInto(const SeparableSurface& s, int nu, int nv, Mesh& m) {
  const Tabulation t = tabulate(s, nu, nv);
  const size_t n = static_cast<size_t>(nu + 1) * (nv + 1);
  if (m.nu != nu || m.nv != nv || m.uvs.size() != 2 * n) buildGridData(nu, nv, m);
  m.nu = nu;
  m.nv = nv;
  m.positions.resize(3 * n);
  m.normals.resize(3 * n);
  float* pos = m.positions.data();
  float* nrm = m.normals.data();
  std::vector<size_t> poles;
  const size_t w = static_cast<size_t>(nu) + 1;
  combineRows(t, [&](int j, const Row& row) {
    const double *x = row.X[0].data(), *y = row.X[1].data(), *z = row.X[2].data();
    const double *xu = row.Xu[0].data(), *yu = row.Xu[1].data(), *zu = row.Xu[2].data();
    const double *xv = row.Xv[0].data(), *yv = row.Xv[1].data(), *zv = row.Xv[2].data();
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
    if (pole)  // rare: find the pole vertices of this row again
      for (size_t i = 0; i < w; ++i)
        if (q[3 * i] == 0 && q[3 * i + 1] == 0 && q[3 * i + 2] == 0) poles.push_back(j * w + i);
  });
  repairPoleNormals(poles, nu, nv, m);
}

Mesh tessellate(const SeparableSurface& s, int nu, int nv) {
  Mesh m;
  tessellateInto(s, nu, nv, m);
  return m;
}

}  // namespace pdesurf
