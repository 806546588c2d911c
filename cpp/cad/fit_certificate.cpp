#include "cad/fit_certificate.hpp"

#include <algorithm>
#include <Eigen/Geometry>
#include <cmath>

#include "cad/grid_partials.hpp"

namespace pdesurf {
namespace {

// The poles of ∂^d/∂t^d along one direction (rows of `p` are poles), with the knots after it.
Eigen::MatrixXd differenced(Eigen::MatrixXd p, std::vector<double> knots, int degree, int d) {
  for (int r = 0; r < d; ++r) {
    const int deg = degree - r;
    if (deg <= 0) return Eigen::MatrixXd::Zero(std::max<Eigen::Index>(p.rows() - 1, 1), p.cols());
    Eigen::MatrixXd q(p.rows() - 1, p.cols());
    for (Eigen::Index i = 0; i + 1 < p.rows(); ++i) {
      const double span = knots[size_t(i) + size_t(deg) + 1] - knots[size_t(i) + 1];
      q.row(i) = span > 0 ? Eigen::RowVectorXd(deg * (p.row(i + 1) - p.row(i)) / span)
                          : Eigen::RowVectorXd::Zero(p.cols());
    }
    knots = std::vector<double>(knots.begin() + 1, knots.end() - 1);
    p.swap(q);
  }
  return p;
}

}  // namespace

FourthBounds splineFourthBounds(const BSplineSurface& b) {
  const int p = b.degreeU, q = b.degreeV;
  // Non-empty spans in knot order: block (i, j) is the i-th non-empty u span.
  std::vector<int> uSpans, vSpans;
  for (int k = p; k < b.countU; ++k)
    if (b.knotsU[size_t(k) + 1] > b.knotsU[size_t(k)]) uSpans.push_back(k);
  for (int k = q; k < b.countV; ++k)
    if (b.knotsV[size_t(k) + 1] > b.knotsV[size_t(k)]) vSpans.push_back(k);
  static const int orders[3][2] = {{4, 0}, {2, 2}, {0, 4}};
  FourthBounds out;
  for (int c = 0; c < 3; ++c) {
    Eigen::MatrixXd net(b.countU, b.countV);
    for (int i = 0; i < b.countU; ++i)
      for (int j = 0; j < b.countV; ++j) net(i, j) = b.pole(i, j)[c];
    for (int o = 0; o < 3; ++o) {
      const int du = orders[o][0], dv = orders[o][1];
      Eigen::MatrixXd d = differenced(net, b.knotsU, p, du);
      d = differenced(d.transpose(), b.knotsV, q, dv).transpose();
      Eigen::MatrixXd& m = out[size_t(o)][size_t(c)];
      m.resize(Eigen::Index(uSpans.size()), Eigen::Index(vSpans.size()));
      for (size_t i = 0; i < uSpans.size(); ++i)
        for (size_t j = 0; j < vSpans.size(); ++j) {
          // Span k's derivative poles after r differences: k - degree .. k - r (convex hull).
          if (du > p || dv > q) {
            m(Eigen::Index(i), Eigen::Index(j)) = 0.0;
            continue;
          }
          const int i0 = uSpans[i] - p, j0 = vSpans[j] - q;
          m(Eigen::Index(i), Eigen::Index(j)) =
              d.block(i0, j0, p - du + 1, q - dv + 1).cwiseAbs().maxCoeff() * (1 + 1e-13);
        }
    }
  }
  return out;
}

Certificate certify(const CertificateGrid& g, const SurfaceOnGrid& S, const BSplineSurface& b, const FourthBounds& bs,
                    const FourthBounds& bb, double tolerance, double normalToleranceDeg) {
  const Eigen::Index mu = Eigen::Index(g.u.size()), mv = Eigen::Index(g.v.size());
  Certificate out;
  // The cells' squared half-widths once.
  std::vector<double> h2(size_t(std::max<Eigen::Index>(mu - 1, 0))), k2(size_t(std::max<Eigen::Index>(mv - 1, 0)));
  for (Eigen::Index i = 0; i + 1 < mu; ++i) h2[size_t(i)] = (g.u[size_t(i) + 1] - g.u[size_t(i)]) * (g.u[size_t(i) + 1] - g.u[size_t(i)]) / 8;
  for (Eigen::Index j = 0; j + 1 < mv; ++j) k2[size_t(j)] = (g.v[size_t(j) + 1] - g.v[size_t(j)]) * (g.v[size_t(j) + 1] - g.v[size_t(j)]) / 8;
  // The border rows' tangents of S and errors of B, for the normals once every block is done
  // (the test of an ill-conditioned normal is relative to the largest tangents on the patch).
  std::array<Eigen::MatrixXd, 2> borderSu, borderSv, borderEu, borderEv;  // 3 × mv each
  for (int side = 0; side < 2; ++side)
    for (auto* m : {&borderSu, &borderSv, &borderEu, &borderEv}) (*m)[size_t(side)].resize(3, mv);
  double maxSu2 = 0, maxSv2 = 0;
  // A block of columns at a time (one column shared with the next block): e = S - B there.
  for (Eigen::Index j0 = 0; j0 + 1 < mv || (mv == 1 && j0 == 0); j0 += kCertificateBlock) {
    const Eigen::Index j1 = std::min(j0 + kCertificateBlock, mv - 1), nb = j1 - j0 + 1;
    const std::vector<double> vb(g.v.begin() + j0, g.v.begin() + j1 + 1);
    GridPartials e = S.at(vb, 5);
    {
      Eigen::MatrixXd su2 = Eigen::MatrixXd::Zero(mu, nb), sv2 = su2;
      for (int c = 0; c < 3; ++c) su2 += e[1][size_t(c)].cwiseAbs2(), sv2 += e[2][size_t(c)].cwiseAbs2();
      maxSu2 = std::max(maxSu2, su2.maxCoeff()), maxSv2 = std::max(maxSv2, sv2.maxCoeff());
    }
    for (int side = 0; side < 2; ++side)
      for (int c = 0; c < 3; ++c) {
        borderSu[size_t(side)].row(c).segment(j0, nb) = e[1][size_t(c)].row(side ? mu - 1 : 0);
        borderSv[size_t(side)].row(c).segment(j0, nb) = e[2][size_t(c)].row(side ? mu - 1 : 0);
      }
    subtractSpline(b, g.u, vb, e);
    for (int side = 0; side < 2; ++side)
      for (int c = 0; c < 3; ++c) {
        borderEu[size_t(side)].row(c).segment(j0, nb) = e[1][size_t(c)].row(side ? mu - 1 : 0);
        borderEv[size_t(side)].row(c).segment(j0, nb) = e[2][size_t(c)].row(side ? mu - 1 : 0);
      }
    Eigen::MatrixXd pointError = Eigen::MatrixXd::Zero(mu, nb);
    for (int c = 0; c < 3; ++c) pointError += e[0][size_t(c)].cwiseAbs2();
    pointError = pointError.cwiseSqrt();
    out.sampled = std::max(out.sampled, pointError.maxCoeff());
    // Column-major: i runs inside (contiguous).
    for (Eigen::Index jj = 0; jj + 1 < nb; ++jj)
      for (Eigen::Index i = 0; i + 1 < mu; ++i) {
        const Eigen::Index j = j0 + jj;
        const double h = h2[size_t(i)], k = k2[size_t(j)];
        const int su = g.uSpan[size_t(i)], sv = g.vSpan[size_t(j)];
        double sum2 = 0.0, uPart = 0.0, vPart = 0.0;
        auto corners = [&](const Eigen::MatrixXd& m) {
          return std::max(std::max(std::abs(m(i, jj)), std::abs(m(i + 1, jj))), std::max(std::abs(m(i, jj + 1)), std::abs(m(i + 1, jj + 1))));
        };
        for (int c = 0; c < 3; ++c) {
          const double a40 = bs[0][size_t(c)](su, sv) + bb[0][size_t(c)](su, sv);
          const double a22 = bs[1][size_t(c)](su, sv) + bb[1][size_t(c)](su, sv);
          const double a04 = bs[2][size_t(c)](su, sv) + bb[2][size_t(c)](su, sv);
          // One level down: e_uu and e_vv over the cell, from their corners and e's fourth derivatives.
          const double muu = corners(e[3][size_t(c)]) + h * a40 + k * a22;
          const double mvv = corners(e[4][size_t(c)]) + h * a22 + k * a04;
          const double bound = corners(e[0][size_t(c)]) + h * muu + k * mvv;
          sum2 += bound * bound;
          uPart += (h * muu) * (h * muu);
          vPart += (k * mvv) * (k * mvv);
        }
        const double cell = std::sqrt(sum2) * (1 + 1e-12);
        out.bound = std::max(out.bound, cell);
        if (!(cell <= tolerance))
          out.failed.push_back({i, j, cell, corners(pointError), 0.0, std::sqrt(uPart), std::sqrt(vPart)});
      }
  }
  // Normals: the angle between S_u × S_v and B_u × B_v on the borders u = u0 and u = u1,
  // where a patch's ends join (a blend's, a fill's side, a primary's trimline), skipping points where S's own
  // normal is ill-conditioned in the parameters: a tangent under 1% of its largest on the patch
  // (a collapsed or nearly collapsed border: the normal's error there is e_v / |S_v|) or
  // tangents within 0.06° of parallel.
  const double maxSu = std::sqrt(maxSu2), maxSv = std::sqrt(maxSv2);
  std::array<std::vector<double>, 2> angle{std::vector<double>(size_t(mv), 0.0), std::vector<double>(size_t(mv), 0.0)};
  for (int side = 0; side < 2; ++side)
    for (Eigen::Index j = 0; j < mv; ++j) {
      if (!g.vCrease.empty() && g.vCrease[size_t(j)]) continue;
      const Eigen::Vector3d su = borderSu[size_t(side)].col(j), sv = borderSv[size_t(side)].col(j);
      const Eigen::Vector3d bu = su - borderEu[size_t(side)].col(j), bv = sv - borderEv[size_t(side)].col(j);
      const Eigen::Vector3d ns = su.cross(sv), nb = bu.cross(bv);
      if (ns.norm() <= 1e-3 * su.norm() * sv.norm() || su.norm() <= 1e-2 * maxSu || sv.norm() <= 1e-2 * maxSv) continue;
      angle[size_t(side)][size_t(j)] = std::atan2(ns.cross(nb).norm(), ns.dot(nb)) * 180.0 / M_PI;
      out.normalDeg = std::max(out.normalDeg, angle[size_t(side)][size_t(j)]);
    }
  // A cell's normal figure: the largest at its corners on a border row.
  auto cellNormal = [&](Eigen::Index i, Eigen::Index j) {
    double a = 0;
    for (int side = 0; side < 2; ++side)
      if ((side == 0 && i == 0) || (side == 1 && i + 2 == mu))
        a = std::max({a, angle[size_t(side)][size_t(j)], angle[size_t(side)][size_t(j) + 1]});
    return a;
  };
  for (FailedCell& f : out.failed) f.normalDeg = cellNormal(f.i, f.j);
  // Border cells within the tolerance whose normals miss their target fail too.
  std::vector<Eigen::Index> borderRows{0};
  if (mu > 2) borderRows.push_back(mu - 2);  // one row of cells: both borders are that row
  for (Eigen::Index i : borderRows) {
    std::vector<char> listed(size_t(mv), 0);
    for (const FailedCell& f : out.failed)
      if (f.i == i) listed[size_t(f.j)] = 1;
    for (Eigen::Index j = 0; j + 1 < mv; ++j) {
      const double a = cellNormal(i, j);
      if (!(a <= normalToleranceDeg) && !listed[size_t(j)]) out.failed.push_back({i, j, 0.0, 0.0, a, 0.0, 0.0});
    }
  }
  return out;
}

}  // namespace pdesurf
