#include "analysis/bodies.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "cad/creases.hpp"
#include "common/errors.hpp"
#include "surface/combine_rows.hpp"
#include "surface/mesh.hpp"
#include "surface/tabulation.hpp"

namespace pdesurf {

namespace {

constexpr double kJoinTolerance = 1e-8;  // of the scene's size
constexpr int kCellsU = 16, kCellsV = 32;
const double kGaussX[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
const double kGaussW[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};

// Gauss nodes and weights over the cells between sorted breaks.
void nodes(const std::vector<double>& breaks, std::vector<double>* x, std::vector<double>* w) {
  for (size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double a = breaks[k], b = breaks[k + 1];
    if (!(b > a)) continue;
    for (int p = 0; p < 4; ++p) x->push_back((a + b) / 2 + (b - a) / 2 * kGaussX[p]), w->push_back((b - a) / 2 * kGaussW[p]);
  }
}

std::vector<double> uniform(double a, double b, int n) {
  std::vector<double> out;
  for (int k = 0; k <= n; ++k) out.push_back(k == n ? b : a + (b - a) * k / n);
  return out;
}

// The borders' figures on one 9 × 9 grid, tabulated once (point by point, 42 evaluations a
// face were most of the bodies' time).
void measureBorders(const SeparableSurface& s, FaceMeasure* m) {
  constexpr int n = 8;
  std::vector<Eigen::Vector3d> x(size_t(n + 1) * (n + 1));  // [j * (n + 1) + i]
  try {
    const GridSamples g = sampleGrid(s, n, n);
    for (size_t k = 0; k < x.size(); ++k) x[k] = Eigen::Vector3d(&g.X[3 * k]);
  } catch (const Error&) {  // a partial not finite on a border: point by point, as before
    const std::vector<double> us = uniform(s.u0, s.u1, n), vs = uniform(s.v0, s.v1, n);
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) x[size_t(j) * (n + 1) + i] = evalPoint(s, us[size_t(i)], vs[size_t(j)]);
  }
  const auto at = [&](int i, int j) -> const Eigen::Vector3d& { return x[size_t(j) * (n + 1) + i]; };
  m->seamGap = 0;
  for (int i : {0, n / 2, n}) {
    const double gap = (at(i, 0) - at(i, n)).norm();
    if (!(gap <= m->seamGap)) m->seamGap = gap;  // NaN stays: not closed
  }
  for (int b = 0; b < 4; ++b) {
    double spread = 0;
    for (int k = 0; k <= n; ++k) {
      const Eigen::Vector3d& p = b == 0 ? at(0, k) : b == 1 ? at(n, k) : b == 2 ? at(k, 0) : at(k, n);
      const Eigen::Vector3d& first = b == 0 ? at(0, 0) : b == 1 ? at(n, 0) : b == 2 ? at(0, 0) : at(0, n);
      spread = std::max(spread, (p - first).norm());
    }
    m->borderSpread[b] = spread;
  }
}

// Border b of s (0: u0, 1: u1, 2: v0, 3: v1) at ts along it, from one tabulation of that line.
std::vector<Eigen::Vector3d> borderPointsOf(const SeparableSurface& s, int b, const std::vector<double>& ts) {
  std::vector<Eigen::Vector3d> out(ts.size());
  if (ts.empty()) return out;
  const bool fixedU = b < 2;
  const double at = b == 0 ? s.u0 : b == 1 ? s.u1 : b == 2 ? s.v0 : s.v1;
  try {
    const Tabulation t = fixedU ? tabulateAt(s, {at}, ts, 1) : tabulateAt(s, ts, {at}, 1);
    combineRows(t, [&](int j, const GridRow& row) {
      for (size_t i = 0; i < row.count; ++i) out[fixedU ? size_t(j) : i] = Eigen::Vector3d(row.at(0, 0)[i], row.at(0, 1)[i], row.at(0, 2)[i]);
    });
  } catch (const Error&) {
    // A partial not finite on the border (the rows carry them): its points one by one, a
    // point that is not finite left to the topology to refuse, as before.
    for (size_t k = 0; k < ts.size(); ++k) out[k] = fixedU ? evalPoint(s, at, ts[k]) : evalPoint(s, ts[k], at);
  }
  return out;
}

}  // namespace

// Area and (1/3) ∫ X · (X_u × X_v) of one solved surface, tabulated at the Gauss nodes.
FaceMeasure faceMeasure(const SeparableSurface& s) {
  std::vector<double> ub = uniform(s.u0, s.u1, kCellsU), vb = uniform(s.v0, s.v1, kCellsV);
  for (double f : {1.0 / 256, 1.0 / 128, 1.0 / 64, 1.0 / 32}) ub.push_back(s.u0 + (s.u1 - s.u0) * f);  // towards u0
  for (double c : findCreases(s)) vb.push_back(c);
  std::sort(ub.begin(), ub.end());
  std::sort(vb.begin(), vb.end());
  std::vector<double> ux, uw, vx, vw;
  nodes(ub, &ux, &uw);
  nodes(vb, &vx, &vw);
  const Tabulation t = tabulateAt(s, ux, vx, 1);
  double a = 0, v = 0;
  combineRows(t, [&](int j, const GridRow& row) {
    for (size_t i = 0; i < ux.size(); ++i) {
      const auto vec = [&](int q) { return Eigen::Vector3d(row.at(q, 0)[i], row.at(q, 1)[i], row.at(q, 2)[i]); };
      const Eigen::Vector3d n = vec(1).cross(vec(2));
      a += uw[i] * vw[size_t(j)] * n.norm();
      v += uw[i] * vw[size_t(j)] * vec(0).dot(n);
    }
  });
  FaceMeasure out{a, v / 3};
  measureBorders(s, &out);
  return out;
}

SolvedTopology solvedTopology(const std::vector<SolvedPatch>& solved, double sceneSize, const std::vector<FaceMeasure>* measures) {
  const double tol = kJoinTolerance * sceneSize;
  std::vector<TopologyFace> faces;
  for (const SolvedPatch& sp : solved) {
    const SeparableSurface& s = sp.surface;
    TopologyFace f;
    f.name = sp.patch->name;
    f.u0 = s.u0, f.u1 = s.u1, f.v0 = s.v0, f.v1 = s.v1;
    f.eval = [&s](double u, double v, int du, int dv) { return evalPoint(s, u, v, du, dv); };
    f.borderPoints = [&s](int b, const std::vector<double>& ts) { return borderPointsOf(s, b, ts); };
    const FaceMeasure m = measures ? (*measures)[faces.size()] : faceMeasure(s);
    // Closed in v: both u-borders and the middle meet themselves across v0 = v1.
    f.closedV = m.seamGap <= tol;
    // A collapsed border: its points one (a fill's centre, a cone's apex).
    for (int b = 0; b < 4; ++b) f.degenerate[b] = m.borderSpread[b] <= tol;
    f.area = m.area, f.signedVolume = m.signedVolume;
    faces.push_back(std::move(f));
  }
  SolvedTopology out{std::move(faces), borderJoins(solved), {}};
  out.topology = buildTopology(out.faces, out.joins, tol);
  return out;
}

std::vector<Body> measureBodies(const std::vector<SolvedPatch>& solved, double sceneSize, const std::vector<FaceMeasure>* measures) {
  const SolvedTopology st = solvedTopology(solved, sceneSize, measures);
  const BrepTopology& t = st.topology;
  std::vector<Body> out;
  for (const BrepShell& sh : t.shells) {
    Body b;
    for (int f : sh.faces) b.patches.push_back(solved[size_t(f)].patch->name);
    b.closed = sh.closed;
    b.area = sh.area;
    b.volume = sh.closed ? sh.volume : 0;
    for (int f : sh.faces)
      for (const BrepEdgeUse& u : t.faces[size_t(f)].loop) b.freeEdges += t.edges[size_t(u.edge)].uses == 1;
    out.push_back(std::move(b));
  }
  return out;
}

}  // namespace pdesurf
