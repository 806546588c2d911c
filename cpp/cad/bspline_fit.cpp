#include "cad/bspline_fit.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "cad/creases.hpp"
#include "cad/derivative_bounds.hpp"
#include "cad/fit_certificate.hpp"
#include "cad/grid_partials.hpp"
#include "cad/knots.hpp"
#include "common/errors.hpp"

namespace pdesurf {
namespace {

// Spans on either side halved with one whose border normal misses its target.
constexpr int kNormalSpread = 2;
// Certificate cells per span (a span starts with 4) before the span itself is halved.
constexpr int kMaxCellsPerSpan = 64;

// Grid values: each span cut into its own number of cells; uSpan[i] names the cell's span.
void makeGrid(const std::vector<double>& breaks, const std::vector<int>& cuts, std::vector<double>* t, std::vector<int>* spanOf) {
  t->clear();
  spanOf->clear();
  for (size_t s = 0; s + 1 < breaks.size(); ++s)
    for (int k = 0; k < cuts[s]; ++k) {
      t->push_back(breaks[s] + (breaks[s + 1] - breaks[s]) * k / cuts[s]);
      spanOf->push_back(int(s));
    }
  t->push_back(breaks.back());
}

// Halves the spans marked, carrying their cell counts and which breaks are creases.
void split(std::vector<double>& breaks, std::vector<int>& cuts, std::vector<bool>& crease, const std::vector<bool>& mark) {
  std::vector<double> b{breaks.front()};
  std::vector<int> c;
  std::vector<bool> k{crease.front()};
  for (size_t s = 0; s + 1 < breaks.size(); ++s) {
    if (mark[s]) {
      b.push_back(0.5 * (breaks[s] + breaks[s + 1]));
      c.push_back(cuts[s]);
      k.push_back(false);
    }
    b.push_back(breaks[s + 1]);
    c.push_back(cuts[s]);
    k.push_back(crease[s + 1]);
  }
  breaks.swap(b);
  cuts.swap(c);
  crease.swap(k);
}

// Uniform breaks with the creases put in (a uniform break within a tenth of a span of a
// crease gives way to it).
void withCreases(std::vector<double>& breaks, std::vector<bool>& crease, const std::vector<double>& creases) {
  const double near = 0.1 * (breaks.back() - breaks.front()) / double(breaks.size() - 1);
  std::vector<std::pair<double, bool>> all;
  for (size_t i = 0; i < breaks.size(); ++i) {
    const bool end = i == 0 || i + 1 == breaks.size();
    bool clash = false;
    for (double c : creases) clash = clash || std::abs(c - breaks[i]) < near;
    if (end || !clash) all.push_back({breaks[i], false});
  }
  for (double c : creases) all.push_back({c, true});
  std::sort(all.begin(), all.end());
  breaks.clear();
  crease.clear();
  for (size_t i = 0; i < all.size(); ++i) {
    // A piece between two creases (or a crease and an end) that is a single span is halved: a
    // degree-5 piece of one span has six poles against the five grid points a span starts
    // with (a fill of three sides has such pieces next to its seam).
    if (i > 0 && (all[i].second || i + 1 == all.size()) && (all[i - 1].second || i == 1))
      breaks.push_back((all[i - 1].first + all[i].first) / 2), crease.push_back(false);
    breaks.push_back(all[i].first), crease.push_back(all[i].second);
  }
}

std::vector<double> uniformBreaks(double a, double b, int n) {
  std::vector<double> out;
  for (int i = 0; i <= n; ++i) out.push_back(i == n ? b : a + (b - a) * i / n);
  return out;
}

// Closed in v when the borders v0 and v1 coincide; periodic when the first two derivatives
// across the seam agree too (a periodic basis then keeps the seam smooth).
void seamOf(const SeparableSurface& s, double scale, bool* closed, bool* periodic) {
  *closed = *periodic = false;
  if (!(s.v1 > s.v0)) return;
  double gap = 0, slope = 0, bend = 0, size1 = 0, size2 = 0;
  for (int i = 0; i <= 8; ++i) {
    const double u = s.u0 + (s.u1 - s.u0) * i / 8;
    gap = std::max(gap, (evalPoint(s, u, s.v0) - evalPoint(s, u, s.v1)).norm());
    const Eigen::Vector3d a1 = evalPoint(s, u, s.v0, 0, 1), b1 = evalPoint(s, u, s.v1, 0, 1);
    const Eigen::Vector3d a2 = evalPoint(s, u, s.v0, 0, 2), b2 = evalPoint(s, u, s.v1, 0, 2);
    slope = std::max(slope, (a1 - b1).norm());
    bend = std::max(bend, (a2 - b2).norm());
    size1 = std::max(size1, a1.norm());
    size2 = std::max(size2, a2.norm());
  }
  *closed = gap <= 1e-9 * scale;
  *periodic = *closed && slope <= 1e-7 * std::max(size1, scale) && bend <= 1e-6 * std::max(size2, scale);
}

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

FourthBounds boundFourth(const SeparableSurface& s, const std::vector<double>& ub, const std::vector<double>& vb,
                         GeneralBoundCache* cache) {
  return {boundPartials(s, 4, 0, ub, vb, cache), boundPartials(s, 2, 2, ub, vb, cache), boundPartials(s, 0, 4, ub, vb, cache)};
}

}  // namespace

BSplineSurface fitSurface(const SeparableSurface& s, const FitOptions& o, FitReport* report) {
  if (!(o.tolerance > 0) || !std::isfinite(o.tolerance))
    throw Error(ErrorCode::InvalidField, "tolerance: must be a positive finite number, not " + number(o.tolerance));
  if (o.degree != 3 && o.degree != 5) throw Error(ErrorCode::InvalidField, "degree: must be 3 or 5");
  FitReport rep;
  const int p = o.degree, q = o.degree;
  // Scale from a coarse look: the degenerate-border and seam tests are relative to it.
  {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(HUGE_VAL), hi = -lo;
    for (int i = 0; i <= 16; ++i)
      for (int j = 0; j <= 16; ++j) {
        const Eigen::Vector3d x = evalPoint(s, s.u0 + (s.u1 - s.u0) * i / 16, s.v0 + (s.v1 - s.v0) * j / 16);
        lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
      }
    rep.scale = (hi - lo).norm();
    if (!std::isfinite(rep.scale)) throw Error(ErrorCode::NonFinite, "the surface is not finite");
  }
  bool closed = false, periodic = false;
  seamOf(s, rep.scale, &closed, &periodic);
  bool kinkAtEnds = false;
  const std::vector<double> creases = findCreases(s, &kinkAtEnds);
  periodic = periodic && creases.empty();
  rep.periodicV = periodic;
  rep.creases = int(creases.size());
  std::vector<double> ub = uniformBreaks(s.u0, s.u1, 4), vb = uniformBreaks(s.v0, s.v1, periodic ? 8 : 4);
  std::vector<bool> uCrease(ub.size(), false), vCrease(vb.size(), false);
  withCreases(vb, vCrease, creases);
  std::vector<int> ucut(ub.size() - 1, 4), vcut(vb.size() - 1, 4);
  BSplineSurface best;
  double reached = HUGE_VAL;
  GeneralBoundCache boundCache;
  for (int iter = 1;; ++iter) {
    CertificateGrid grid;
    makeGrid(ub, ucut, &grid.u, &grid.uSpan);
    makeGrid(vb, vcut, &grid.v, &grid.vSpan);
    grid.vCrease.assign(grid.v.size(), false);
    for (size_t j = 0; j < grid.v.size(); ++j) {
      const size_t span = size_t(grid.vSpan[std::min(j, grid.vSpan.size() - 1)]);
      for (size_t b : {span, span + 1})
        if (vCrease[b] && grid.v[j] == vb[b]) grid.vCrease[j] = true;
    }
    // A seam that is not smooth (closed, not periodic) is a crease too.
    if ((closed && !periodic) || kinkAtEnds) grid.vCrease.front() = grid.vCrease.back() = true;
    const long points = long(grid.u.size()) * long(grid.v.size());
    const int nsu = int(ub.size()) - 1, nsv = int(vb.size()) - 1;
    if (iter > kFitMaxIterations || nsu > kFitMaxSpans || nsv > kFitMaxSpans || points > kFitMaxGridPoints) {
      // The tolerance is a promise; the normals' target is best effort: a fit within the
      // tolerance is kept and reports the normals it reached (normalsMet false).
      if (reached <= o.tolerance) break;
      throw Error(ErrorCode::TooLarge,
                  "the fit reached a certified deviation of " + number(reached) + " (tolerance " + number(o.tolerance) +
                      "), normals within " + number(rep.normalDeviationDeg) + "° (" + number(o.normalToleranceDeg) + "°)" +
                      " (limits: " + std::to_string(kFitMaxSpans) + " spans per direction, " + std::to_string(kFitMaxGridPoints) +
                      " certificate points, " + std::to_string(kFitMaxIterations) + " refinements)");
    }
    const GridPartials S = tabulateSurface(s, grid.u, grid.v);
    // Least squares, one direction at a time (the grid is a tensor product).
    const std::vector<double> ku = clampedKnots(ub, p);
    const std::vector<double> kvFit = periodic ? periodicKnots(vb, q) : clampedKnots(vb, q, &vCrease);
    const Eigen::SparseMatrix<double> Au = collocation(ku, p, grid.u, 0);
    const Eigen::SparseMatrix<double> Av = collocation(kvFit, q, grid.v, 0, periodic ? nsv : 0);
    const Eigen::SparseMatrix<double> AvT = Av.transpose();
    // In u, the two outer pole rows at each end are fixed by S and S_u there (Hermite), so
    // B meets a neighbour's border and its tangent plane to the accuracy of a curve fit in v,
    // not of the surface fit's error over the first span's width; the rows between are least squares.
    const int n = int(ku.size()) - p - 1, inner = n - 4;
    const Eigen::SparseMatrix<double> Af = Au.middleCols(2, inner), AfT = Af.transpose();
    Eigen::MatrixXd Ac(Au.rows(), 4);
    Ac << Eigen::MatrixXd(Au.col(0)), Eigen::MatrixXd(Au.col(1)), Eigen::MatrixXd(Au.col(n - 2)), Eigen::MatrixXd(Au.col(n - 1));
    // The normal matrices are banded (degree + 1 wide, plus the periodic wrap): sparse Cholesky.
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> nu, nv;
    if (inner > 0) nu.compute(AfT * Af);
    nv.compute(AvT * Av);
    if ((inner > 0 && nu.info() != Eigen::Success) || nv.info() != Eigen::Success)
      throw Error(ErrorCode::Singular, std::string("the fit's least-squares system is singular (in ") + (nv.info() != Eigen::Success ? "v, " : "u, ") +
                                           std::to_string(nsu) + " × " + std::to_string(nsv) + " spans)");
    const double startStep = (ku[size_t(p) + 1] - ku[1]) / p, endStep = (ku[size_t(n + p - 1)] - ku[size_t(n - 1)]) / p;
    std::vector<double> uResidual(size_t(nsu), 0.0), vResidual(size_t(nsv), 0.0);
    Eigen::MatrixXd ru = Eigen::MatrixXd::Zero(Au.rows(), Av.rows()), rv = ru;
    // u-poles of data X (u rows, any columns) with the end rows fixed by the values and the
    // u-derivatives du0, du1 at u0 and u1.
    auto fitU = [&](const Eigen::MatrixXd& X, const Eigen::MatrixXd& du0, const Eigen::MatrixXd& du1) {
      const Eigen::Index last = X.rows() - 1;
      Eigen::MatrixXd fixed(4, X.cols());
      fixed << X.row(0), X.row(0) + startStep * du0, X.row(last) - endStep * du1, X.row(last);
      Eigen::MatrixXd cu(n, X.cols());
      cu.row(0) = fixed.row(0), cu.row(1) = fixed.row(1), cu.row(n - 2) = fixed.row(2), cu.row(n - 1) = fixed.row(3);
      if (inner > 0) cu.middleRows(2, inner) = nu.solve(AfT * (X - Ac * fixed));
      return cu;
    };
    // A v-range that is not periodic gets the same Hermite ends in v (an open patch's corners
    // then meet too; a closed one's seam, a crease, is one-sided on each side): the end
    // columns from S and S_v at v0 and v1, S_v's own u-fit ended by S_uv at the corners
    // (not where a kink sits at an end: S_v there is two-sided).
    const bool hermiteV = !periodic && !kinkAtEnds;
    const int m = int(Av.cols()), innerV = m - 4;
    Eigen::SparseMatrix<double> AvfT;
    Eigen::MatrixXd Avc;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> nvf;
    double startStepV = 0, endStepV = 0;
    if (hermiteV) {
      const Eigen::SparseMatrix<double> Avf = Av.middleCols(2, innerV);
      AvfT = Avf.transpose();
      Avc.resize(Av.rows(), 4);
      Avc << Eigen::MatrixXd(Av.col(0)), Eigen::MatrixXd(Av.col(1)), Eigen::MatrixXd(Av.col(m - 2)), Eigen::MatrixXd(Av.col(m - 1));
      if (innerV > 0) nvf.compute(AvfT * Avf);
      startStepV = (kvFit[size_t(q) + 1] - kvFit[1]) / q, endStepV = (kvFit[size_t(m + q - 1)] - kvFit[size_t(m - 1)]) / q;
    }
    Eigen::Vector3d twist[2][2];  // S_uv at the corners (u end, v end)
    if (hermiteV)
      for (int a = 0; a < 2; ++a)
        for (int b2 = 0; b2 < 2; ++b2) twist[a][b2] = evalPoint(s, a ? s.u1 : s.u0, b2 ? s.v1 : s.v0, 1, 1);
    std::array<Eigen::MatrixXd, 3> net;
    for (int c = 0; c < 3; ++c) {
      const Eigen::MatrixXd& X = S[0][size_t(c)];
      const Eigen::MatrixXd& Xu = S[1][size_t(c)];
      const Eigen::MatrixXd& Xv = S[2][size_t(c)];
      const Eigen::Index last = X.rows() - 1, lastV = X.cols() - 1;
      const Eigen::MatrixXd cu = fitU(X, Xu.row(0), Xu.row(last));  // u-poles, v samples
      if (hermiteV) {
        Eigen::MatrixXd d0(1, 1), d1(1, 1), e0(1, 1), e1(1, 1);
        d0(0, 0) = twist[0][0][c], d1(0, 0) = twist[1][0][c], e0(0, 0) = twist[0][1][c], e1(0, 0) = twist[1][1][c];
        const Eigen::MatrixXd sv0 = fitU(Xv.col(0), d0, d1), sv1 = fitU(Xv.col(lastV), e0, e1);
        Eigen::MatrixXd fixedV(n, 4);
        fixedV << cu.col(0), cu.col(0) + startStepV * sv0, cu.col(lastV) - endStepV * sv1, cu.col(lastV);
        Eigen::MatrixXd poles(n, m);
        poles.col(0) = fixedV.col(0), poles.col(1) = fixedV.col(1), poles.col(m - 2) = fixedV.col(2), poles.col(m - 1) = fixedV.col(3);
        if (innerV > 0) poles.middleCols(2, innerV) = nvf.solve(AvfT * (cu.transpose() - Avc * fixedV.transpose())).transpose();
        net[size_t(c)] = poles;
      } else {
        net[size_t(c)] = nv.solve(AvT * cu.transpose()).transpose();
      }
      // Each direction's own 1D error says which spans to halve.
      ru += (X - Au * cu).cwiseAbs2();
      const Eigen::MatrixXd cv = nv.solve(AvT * X.transpose());
      rv += (X.transpose() - Av * cv).cwiseAbs2().transpose();
    }
    for (Eigen::Index i = 0; i < ru.rows(); ++i)
      for (Eigen::Index j = 0; j < ru.cols(); ++j) {
        const int su = grid.uSpan[size_t(std::min<Eigen::Index>(i, Eigen::Index(grid.uSpan.size()) - 1))];
        const int sv = grid.vSpan[size_t(std::min<Eigen::Index>(j, Eigen::Index(grid.vSpan.size()) - 1))];
        uResidual[size_t(su)] = std::max(uResidual[size_t(su)], std::sqrt(ru(i, j)));
        vResidual[size_t(sv)] = std::max(vResidual[size_t(sv)], std::sqrt(rv(i, j)));
      }
    BSplineSurface b;
    b.degreeU = p;
    b.degreeV = q;
    b.knotsU = ku;
    b.countU = int(ku.size()) - p - 1;
    Eigen::MatrixXd vPoles;  // rows along v, columns (component, u index)
    {
      Eigen::MatrixXd stacked(net[0].cols(), 3 * b.countU);
      for (int c = 0; c < 3; ++c) stacked.middleCols(c * b.countU, b.countU) = net[size_t(c)].transpose();
      if (periodic) {
        periodicToClamped(vb, q, stacked, &b.knotsV, &vPoles);
      } else {
        b.knotsV = kvFit;
        vPoles = stacked;
        if (closed) vPoles.row(vPoles.rows() - 1) = vPoles.row(0) = 0.5 * (vPoles.row(0) + vPoles.row(vPoles.rows() - 1));
      }
    }
    b.countV = int(vPoles.rows());
    b.closedV = closed;
    b.poles.resize(size_t(b.countU) * b.countV);
    for (int i = 0; i < b.countU; ++i)
      for (int j = 0; j < b.countV; ++j)
        b.pole(i, j) = Eigen::Vector3d(vPoles(j, i), vPoles(j, b.countU + i), vPoles(j, 2 * b.countU + i));
    // A border of S that is one point (a fill's centre) stays one point in B.
    for (int side = 0; side < 2; ++side) {
      const Eigen::Index row = side ? Eigen::Index(grid.u.size()) - 1 : 0;
      Eigen::Vector3d first(S[0][0](row, 0), S[0][1](row, 0), S[0][2](row, 0));
      double spread = 0;
      for (Eigen::Index j = 0; j < Eigen::Index(grid.v.size()); ++j)
        spread = std::max(spread, (Eigen::Vector3d(S[0][0](row, j), S[0][1](row, j), S[0][2](row, j)) - first).norm());
      if (spread <= 1e-12 * rep.scale) {
        b.degenerate[side] = true;
        for (int j = 0; j < b.countV; ++j) b.pole(side ? b.countU - 1 : 0, j) = first;
      }
    }
    const FourthBounds boundS = boundFourth(s, ub, vb, &boundCache), boundB = splineFourthBounds(b);
    const Certificate cert = certify(grid, S, tabulateSpline(b, grid.u, grid.v), boundS, boundB, rep.scale);
    const bool normalsMet = cert.normalDeg <= o.normalToleranceDeg;
    // Best so far: within the tolerance with the smallest normal deviation, else the smallest bound.
    const bool better = cert.bound <= o.tolerance
                            ? (reached > o.tolerance || cert.normalDeg < rep.normalDeviationDeg)
                            : cert.bound < reached;
    if (better) {
      reached = cert.bound;
      rep.normalsMet = normalsMet;
      best = b;
      rep.deviation = cert.bound;
      rep.sampledDeviation = cert.sampled;
      rep.normalDeviationDeg = cert.normalDeg;
      rep.gridPoints = points;
    }
    rep.iterations = iter;
    if (cert.bound <= o.tolerance && normalsMet) break;
    // Halve a span whose own direction misses a quarter of the tolerance; where a cell fails
    // with both its spans fitting, its samples are close and the bound's slack is the cause:
    // cut that cell's span finer in the direction that dominates the slack.
    std::vector<bool> markU(static_cast<size_t>(nsu)), markV(static_cast<size_t>(nsv));
    for (int i = 0; i < nsu; ++i) markU[size_t(i)] = !(uResidual[size_t(i)] <= o.tolerance / 4);
    for (int j = 0; j < nsv; ++j) markV[size_t(j)] = !(vResidual[size_t(j)] <= o.tolerance / 4);
    std::vector<bool> finerU(static_cast<size_t>(nsu)), finerV(static_cast<size_t>(nsv));
    for (Eigen::Index i = 0; i < cert.cell.rows(); ++i)
      for (Eigen::Index j = 0; j < cert.cell.cols(); ++j) {
        const bool normalMissed = !(cert.cellNormalDeg(i, j) <= o.normalToleranceDeg);
        if (cert.cell(i, j) <= o.tolerance && !normalMissed) continue;
        const int su = grid.uSpan[size_t(i)], sv = grid.vSpan[size_t(j)];
        if (normalMissed) {
          // A border's normal is B_u × B_v there, and both are v-fits (the u-ends are Hermite:
          // B_u is the v-fit of S_u, B_v the derivative of the v-fit of S): the v-spans decide
          // it. A span's position error e shows in B_v as about e / h, and least squares spreads
          // e from the neighbours into a span halved alone: halve its neighbours with it.
          for (int d = -kNormalSpread; d <= kNormalSpread; ++d) {
            const int k = periodic ? ((sv + d) % nsv + nsv) % nsv : std::clamp(sv + d, 0, nsv - 1);
            markV[size_t(k)] = true;
          }
        } else if (markU[size_t(su)] || markV[size_t(sv)]) {
          continue;  // refined anyway where its own direction's residual says so
        } else if (!(cert.cellSampled(i, j) <= o.tolerance / 2)) {
          markU[size_t(su)] = markV[size_t(sv)] = true;
        } else if (cert.uDominant(i, j)) {
          finerU[size_t(su)] = true;
        } else {
          finerV[size_t(sv)] = true;
        }
      }
    // Finer cells shrink the bound's h² terms, but S's fourth-derivative bound stays the whole
    // span's: past kMaxCellsPerSpan a span is halved instead, so the bound becomes the halves'
    // own (a fill's boundary layer bounded over its first span had the cells of a span near its
    // end refined to 1024 and the certificate points run out 14 % short of the tolerance).
    for (int i = 0; i < nsu; ++i)
      if (finerU[size_t(i)] && !markU[size_t(i)]) {
        if (ucut[size_t(i)] >= kMaxCellsPerSpan) markU[size_t(i)] = true;
        else ucut[size_t(i)] *= 2;
      }
    for (int j = 0; j < nsv; ++j)
      if (finerV[size_t(j)] && !markV[size_t(j)]) {
        if (vcut[size_t(j)] >= kMaxCellsPerSpan) markV[size_t(j)] = true;
        else vcut[size_t(j)] *= 2;
      }
    split(ub, ucut, uCrease, markU);
    split(vb, vcut, vCrease, markV);
  }
  best.name.clear();
  if (report) *report = rep;
  return best;
}

BSplineSurface bezierAsBSpline(int n, int m, const std::vector<Eigen::Vector3d>& net) {
  BSplineSurface b;
  b.degreeU = n;
  b.degreeV = m;
  b.countU = n + 1;
  b.countV = m + 1;
  b.knotsU = clampedKnots({0.0, 1.0}, n);
  b.knotsV = clampedKnots({0.0, 1.0}, m);
  b.poles = net;
  return b;
}

}  // namespace pdesurf
