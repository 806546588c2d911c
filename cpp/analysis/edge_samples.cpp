#include "analysis/edge_samples.hpp"

#include "surface/combine_rows.hpp"

namespace pdesurf {

namespace {
// samples points from a0 to a1, both ends exact (as tabulate() spaces a grid line).
std::vector<double> gridLine(double a0, double a1, int samples) {
  std::vector<double> x(samples);
  for (int i = 0; i < samples; ++i) x[i] = i == samples - 1 ? a1 : a0 + (a1 - a0) * i / (samples - 1);
  return x;
}
}  // namespace

std::vector<EdgePoint> edgeSamples(const SeparableSurface& surface, bool alongU, int end, double a0, double a1, int samples) {
  SeparableSurface s = surface;  // the factors are functions of absolute u and v: only the ranges change
  const double sign = end == 0 ? 1.0 : -1.0;
  std::vector<EdgePoint> out(samples);
  auto vec = [](const GridRow& row, int q, size_t i) { return Eigen::Vector3d(row.d[q][0][i], row.d[q][1][i], row.d[q][2][i]); };
  // Only the edge's own line is tabulated (a pointwise program costs per point).
  if (!alongU) {
    s.v0 = a0, s.v1 = a1;
    const Tabulation t = tabulateAt(s, {end ? s.u1 : s.u0}, gridLine(a0, a1, samples), 2);
    combineRows(t, [&](int j, const GridRow& row) {
      out[j] = {vec(row, 0, 0), vec(row, 2, 0), sign * vec(row, 1, 0), vec(row, 3, 0), vec(row, 5, 0), sign * vec(row, 4, 0)};
    });
  } else {
    s.u0 = a0, s.u1 = a1;
    const Tabulation t = tabulateAt(s, gridLine(a0, a1, samples), {end ? s.v1 : s.v0}, 2);
    combineRows(t, [&](int, const GridRow& row) {
      for (int i = 0; i < samples; ++i)
        out[i] = {vec(row, 0, i), vec(row, 1, i), sign * vec(row, 2, i), vec(row, 5, i), vec(row, 3, i), sign * vec(row, 4, i)};
    });
  }
  return out;
}

std::vector<EdgePoint> edgeSamplesAt(const SeparableSurface& s, bool alongU, int end, const std::vector<double>& at) {
  std::vector<EdgePoint> out(at.size());
  if (at.size() < 2 || at.size() > size_t(kMaxGrid) + 1) {
    for (size_t k = 0; k < at.size(); ++k) {
      const double u = alongU ? at[k] : (end ? s.u1 : s.u0), v = alongU ? (end ? s.v1 : s.v0) : at[k];
      const Eigen::Vector3d X = evalPoint(s, u, v), Xu = evalPoint(s, u, v, 1, 0), Xv = evalPoint(s, u, v, 0, 1);
      const Eigen::Vector3d Xuu = evalPoint(s, u, v, 2, 0), Xuv = evalPoint(s, u, v, 1, 1), Xvv = evalPoint(s, u, v, 0, 2);
      out[k] = edgePointFrom(alongU, end, X, Xu, Xv, Xuu, Xuv, Xvv);
    }
    return out;
  }
  // One tabulation at the edge's parameters and the two ends across it.
  auto vec = [](const GridRow& row, int q, size_t i) { return Eigen::Vector3d(row.d[q][0][i], row.d[q][1][i], row.d[q][2][i]); };
  auto point = [&](const GridRow& row, size_t i) {
    return edgePointFrom(alongU, end, vec(row, 0, i), vec(row, 1, i), vec(row, 2, i), vec(row, 3, i), vec(row, 4, i), vec(row, 5, i));
  };
  if (!alongU) {
    const Tabulation t = tabulateAt(s, {end ? s.u1 : s.u0}, at, 2);
    combineRows(t, [&](int j, const GridRow& row) { out[size_t(j)] = point(row, 0); });
  } else {
    const Tabulation t = tabulateAt(s, at, {end ? s.v1 : s.v0}, 2);
    combineRows(t, [&](int, const GridRow& row) {
      for (size_t i = 0; i < at.size(); ++i) out[i] = point(row, i);
    });
  }
  return out;
}

}  // namespace pdesurf
