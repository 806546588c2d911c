#include "surface/mesh.hpp"

#include <cmath>

#include "surface/tabulation.hpp"

namespace pdesurf {

namespace {

// Walks the grid once, combining the tabulated factors; calls emit(vertex, X[3], Xu[3], Xv[3]).
template <class Emit>
void combine(const Tabulation& t, Emit&& emit) {
  const int nu = t.nu, nv = t.nv;
  for (int j = 0; j <= nv; ++j) {
    for (int i = 0; i <= nu; ++i) {
      double X[3], Xu[3], Xv[3];
      for (int c = 0; c < 3; ++c) {
        const int T = t.terms[c];
        const double* gu = t.uTab[c].data() + static_cast<size_t>(i) * 2 * T;
        const double* gv = t.vTab[c].data() + static_cast<size_t>(j) * 2 * T;
        double x = 0, xu = 0, xv = 0;
        for (int k = 0; k < T; ++k) {
          x += gu[2 * k] * gv[2 * k];
          xu += gu[2 * k + 1] * gv[2 * k];
          xv += gu[2 * k] * gv[2 * k + 1];
        }
        X[c] = x;
        Xu[c] = xu;
        Xv[c] = xv;
      }
      emit(static_cast<size_t>(j) * (nu + 1) + i, X, Xu, Xv);
    }
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
  combine(t, [&](size_t idx, const double* X, const double* Xu, const double* Xv) {
    for (int c = 0; c < 3; ++c) {
      g.X[3 * idx + c] = X[c];
      g.Xu[3 * idx + c] = Xu[c];
      g.Xv[3 * idx + c] = Xv[c];
    }
  });
  return g;
}

Mesh tessellate(const SeparableSurface& s, int nu, int nv) {
  const Tabulation t = tabulate(s, nu, nv);
  Mesh m;
  m.nu = nu;
  m.nv = nv;
  const size_t n = static_cast<size_t>(nu + 1) * (nv + 1);
  m.positions.resize(3 * n);
  m.normals.resize(3 * n);
  m.uvs.resize(2 * n);
  std::vector<uint8_t> degenerate(n, 0);
  combine(t, [&](size_t idx, const double* X, const double* Xu, const double* Xv) {
    const double nx = Xu[1] * Xv[2] - Xu[2] * Xv[1];
    const double ny = Xu[2] * Xv[0] - Xu[0] * Xv[2];
    const double nz = Xu[0] * Xv[1] - Xu[1] * Xv[0];
    const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
    const double scale = std::sqrt((Xu[0] * Xu[0] + Xu[1] * Xu[1] + Xu[2] * Xu[2]) * (Xv[0] * Xv[0] + Xv[1] * Xv[1] + Xv[2] * Xv[2]));
    const double inv = len > 1e-12 * scale && len > 0 ? 1.0 / len : 0.0;
    degenerate[idx] = inv == 0.0;
    for (int c = 0; c < 3; ++c) m.positions[3 * idx + c] = static_cast<float>(X[c]);
    m.normals[3 * idx + 0] = static_cast<float>(nx * inv);
    m.normals[3 * idx + 1] = static_cast<float>(ny * inv);
    m.normals[3 * idx + 2] = static_cast<float>(nz * inv);
  });
  // Poles (X_u × X_v = 0) borrow the normal of the nearest regular vertex along u, then v.
  for (size_t idx = 0; idx < n; ++idx) {
    if (!degenerate[idx]) continue;
    const int i = static_cast<int>(idx % (nu + 1)), j = static_cast<int>(idx / (nu + 1));
    for (int step = 1; step <= 4; ++step) {  // a few cells; a fully collapsed patch keeps zero normals
      const int cand[4][2] = {{i + step, j}, {i - step, j}, {i, j + step}, {i, j - step}};
      bool found = false;
      for (const auto& c : cand) {
        if (c[0] < 0 || c[0] > nu || c[1] < 0 || c[1] > nv) continue;
        const size_t k = static_cast<size_t>(c[1]) * (nu + 1) + c[0];
        if (degenerate[k]) continue;
        for (int d = 0; d < 3; ++d) m.normals[3 * idx + d] = m.normals[3 * k + d];
        found = true;
        break;
      }
      if (found) break;
    }
  }
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const size_t idx = static_cast<size_t>(j) * (nu + 1) + i;
      m.uvs[2 * idx] = static_cast<float>(i) / nu;
      m.uvs[2 * idx + 1] = static_cast<float>(j) / nv;
    }
  m.indices.reserve(static_cast<size_t>(6) * nu * nv);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const uint32_t a = j * (nu + 1) + i, b = (j + 1) * (nu + 1) + i, c = (j + 1) * (nu + 1) + i + 1, d = j * (nu + 1) + i + 1;
      m.indices.insert(m.indices.end(), {a, b, d, b, c, d});
    }
  return m;
}

}  // namespace pdesurf
