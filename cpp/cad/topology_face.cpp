#include "cad/topology_face.hpp"

#include <Eigen/Geometry>

#include "cad/grid_partials.hpp"

namespace pdesurf {

namespace {

// Σ over the face's cells of a Gauss-Legendre rule (4 × 4) of f(X, X_u, X_v).
template <class F>
double integrate(const TopologyFace& face, F f) {
  static const double x[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  static const double w[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  double sum = 0;
  for (size_t i = 0; i + 1 < face.uCells.size(); ++i) {
    const double a = face.uCells[i], b = face.uCells[i + 1];
    if (!(b > a)) continue;
    for (size_t j = 0; j + 1 < face.vCells.size(); ++j) {
      const double c = face.vCells[j], d = face.vCells[j + 1];
      if (!(d > c)) continue;
      for (int p = 0; p < 4; ++p)
        for (int q = 0; q < 4; ++q) {
          const double u = (a + b) / 2 + (b - a) / 2 * x[p], v = (c + d) / 2 + (d - c) / 2 * x[q];
          sum += w[p] * w[q] * (b - a) * (d - c) / 4 * f(face.eval(u, v, 0, 0), face.eval(u, v, 1, 0), face.eval(u, v, 0, 1));
        }
    }
  }
  return sum;
}

// Gauss-Legendre nodes (4 a cell) and weights over the cells between sorted breaks.
void gaussNodes(const std::vector<double>& breaks, std::vector<double>* x, std::vector<double>* w) {
  static const double gx[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  static const double gw[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  for (size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double a = breaks[i], b = breaks[i + 1];
    if (!(b > a)) continue;
    for (int p = 0; p < 4; ++p) x->push_back((a + b) / 2 + (b - a) / 2 * gx[p]), w->push_back((b - a) / 2 * gw[p]);
  }
}

std::vector<double> distinct(const std::vector<double>& knots) {
  std::vector<double> out;
  for (double k : knots)
    if (out.empty() || k > out.back()) out.push_back(k);
  return out;
}

}  // namespace

double faceArea(const TopologyFace& f) {
  if (!std::isnan(f.area)) return f.area;
  return integrate(f, [](const Eigen::Vector3d&, const Eigen::Vector3d& xu, const Eigen::Vector3d& xv) { return xu.cross(xv).norm(); });
}

double faceSignedVolume(const TopologyFace& f) {
  if (!std::isnan(f.signedVolume)) return f.signedVolume;
  return integrate(f, [](const Eigen::Vector3d& x, const Eigen::Vector3d& xu, const Eigen::Vector3d& xv) { return x.dot(xu.cross(xv)); }) / 3;
}

TopologyFace topologyFace(const BSplineSurface& s) {
  TopologyFace f;
  f.name = s.name;
  f.u0 = s.u0(), f.u1 = s.u1(), f.v0 = s.v0(), f.v1 = s.v1();
  f.closedV = s.closedV;
  for (int b = 0; b < 4; ++b) f.degenerate[b] = s.degenerate[b];
  f.eval = [&s](double u, double v, int du, int dv) { return evaluate(s, u, v, du, dv); };
  f.spline = &s;
  f.uCells = distinct(s.knotsU), f.vCells = distinct(s.knotsV);
  // Area and volume part at once, the spline tabulated at the Gauss nodes of its knot spans
  // (a tensor grid: the basis found once a node, not six times a point).
  std::vector<double> un, uw, vn, vw;
  gaussNodes(f.uCells, &un, &uw);
  gaussNodes(f.vCells, &vn, &vw);
  const GridPartials t = tabulateSpline(s, un, vn);
  double area = 0, volume = 0;
  for (size_t j = 0; j < vn.size(); ++j)
    for (size_t i = 0; i < un.size(); ++i) {
      const auto at = [&](int k) { return Eigen::Vector3d(t[size_t(k)][0](Eigen::Index(i), Eigen::Index(j)), t[size_t(k)][1](Eigen::Index(i), Eigen::Index(j)), t[size_t(k)][2](Eigen::Index(i), Eigen::Index(j))); };
      const Eigen::Vector3d n = at(1).cross(at(2));
      area += uw[i] * vw[j] * n.norm();
      volume += uw[i] * vw[j] * at(0).dot(n);
    }
  f.area = area, f.signedVolume = volume / 3;
  return f;
}

}  // namespace pdesurf
