#include "cad/bspline_fit.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "cad/creases.hpp"
#include "cad/derivative_bounds.hpp"
#include "cad/fit_certificate.hpp"
#include "cad/fit_refinement.hpp"
#include "cad/grid_partials.hpp"
#include "cad/knots.hpp"
#include "common/errors.hpp"

namespace pdesurf {
namespace {

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

// The patch's shape as the fit needs it: its size, its seam, creases at the v ends.
struct Shape {
  double scale = 0;
  bool closed = false, periodic = false, kinkAtEnds = false;
};

struct LeastSquares {
  BSplineSurface surface;
  std::vector<double> uResidual, vResidual;  // each span's largest 1D residual
};

// What the least squares reads of S on the grid: its positions, S_u along the u-ends and S_v
// along the v-ends (not the whole grid's derivatives: the certificate tabulates those by blocks).
struct FitData {
  std::array<Eigen::MatrixXd, 3> X;       // u rows × v columns
  std::array<Eigen::MatrixXd, 3> XuEnds;  // 2 × v: at u0 and u1
  std::array<Eigen::MatrixXd, 3> XvEnds;  // u × 2: at v0 and v1
};

FitData fitData(const SeparableSurface& s, const SurfaceOnGrid& surface, const CertificateGrid& grid) {
  FitData d;
  const GridPartials positions = surface.at(grid.v, 1);
  const GridPartials alongV = SurfaceOnGrid(s, {grid.u.front(), grid.u.back()}).at(grid.v, 2);
  const GridPartials alongU = surface.at({grid.v.front(), grid.v.back()}, 3);
  for (int c = 0; c < 3; ++c) {
    d.X[size_t(c)] = positions[0][size_t(c)];
    d.XuEnds[size_t(c)] = alongV[1][size_t(c)];
    d.XvEnds[size_t(c)] = alongU[2][size_t(c)];
  }
  return d;
}

LeastSquares leastSquares(const SeparableSurface& s, int p, const SpanSet& U, const SpanSet& V, const CertificateGrid& grid,
                          const FitData& S, const Shape& f) {
  const int q = p, nsu = U.count(), nsv = V.count();
  const std::vector<bool>& vCrease = V.crease;
  LeastSquares out;
  // Least squares, one direction at a time (the grid is a tensor product).
  const std::vector<double> ku = clampedKnots(U.breaks, p);
  const std::vector<double> kvFit = f.periodic ? periodicKnots(V.breaks, q) : clampedKnots(V.breaks, q, &vCrease);
  const Eigen::SparseMatrix<double> Au = collocation(ku, p, grid.u, 0);
  const Eigen::SparseMatrix<double> Av = collocation(kvFit, q, grid.v, 0, f.periodic ? nsv : 0);
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
  std::vector<double>& uResidual = out.uResidual;
  std::vector<double>& vResidual = out.vResidual;
  uResidual.assign(size_t(nsu), 0.0), vResidual.assign(size_t(nsv), 0.0);
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
  const bool hermiteV = !f.periodic && !f.kinkAtEnds;
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
    const Eigen::MatrixXd& X = S.X[size_t(c)];
    const Eigen::MatrixXd& Xu = S.XuEnds[size_t(c)];
    const Eigen::MatrixXd& Xv = S.XvEnds[size_t(c)];
    const Eigen::Index lastV = X.cols() - 1;
    const Eigen::MatrixXd cu = fitU(X, Xu.row(0), Xu.row(1));  // u-poles, v samples
    if (hermiteV) {
      Eigen::MatrixXd d0(1, 1), d1(1, 1), e0(1, 1), e1(1, 1);
      d0(0, 0) = twist[0][0][c], d1(0, 0) = twist[1][0][c], e0(0, 0) = twist[0][1][c], e1(0, 0) = twist[1][1][c];
      const Eigen::MatrixXd sv0 = fitU(Xv.col(0), d0, d1), sv1 = fitU(Xv.col(1), e0, e1);
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
  BSplineSurface& b = out.surface;
  b.degreeU = p;
  b.degreeV = q;
  b.knotsU = ku;
  b.countU = int(ku.size()) - p - 1;
  Eigen::MatrixXd vPoles;  // rows along v, columns (component, u index)
  {
    Eigen::MatrixXd stacked(net[0].cols(), 3 * b.countU);
    for (int c = 0; c < 3; ++c) stacked.middleCols(c * b.countU, b.countU) = net[size_t(c)].transpose();
    if (f.periodic) {
      periodicToClamped(V.breaks, q, stacked, &b.knotsV, &vPoles);
    } else {
      b.knotsV = kvFit;
      vPoles = stacked;
      if (f.closed) vPoles.row(vPoles.rows() - 1) = vPoles.row(0) = 0.5 * (vPoles.row(0) + vPoles.row(vPoles.rows() - 1));
    }
  }
  b.countV = int(vPoles.rows());
  b.closedV = f.closed;
  b.poles.resize(size_t(b.countU) * b.countV);
  for (int i = 0; i < b.countU; ++i)
    for (int j = 0; j < b.countV; ++j)
      b.pole(i, j) = Eigen::Vector3d(vPoles(j, i), vPoles(j, b.countU + i), vPoles(j, 2 * b.countU + i));
  // A border of S that is one point (a fill's centre) stays one point in B.
  for (int side = 0; side < 2; ++side) {
    const Eigen::Index row = side ? Eigen::Index(grid.u.size()) - 1 : 0;
    Eigen::Vector3d first(S.X[0](row, 0), S.X[1](row, 0), S.X[2](row, 0));
    double spread = 0;
    for (Eigen::Index j = 0; j < Eigen::Index(grid.v.size()); ++j)
      spread = std::max(spread, (Eigen::Vector3d(S.X[0](row, j), S.X[1](row, j), S.X[2](row, j)) - first).norm());
    if (spread <= 1e-12 * f.scale) {
      b.degenerate[side] = true;
      for (int j = 0; j < b.countV; ++j) b.pole(side ? b.countU - 1 : 0, j) = first;
    }
  }
  return out;
}

}  // namespace

namespace {

// What the fit must respect before it starts: the surface's size (from a coarse look: the
// degenerate-border and seam tests are relative to it), a seam, and the creases along v.
Shape shapeOf(const SeparableSurface& s, std::vector<double>* creases) {
  Shape shape;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(HUGE_VAL), hi = -lo;
  for (int i = 0; i <= 16; ++i)
    for (int j = 0; j <= 16; ++j) {
      const Eigen::Vector3d x = evalPoint(s, s.u0 + (s.u1 - s.u0) * i / 16, s.v0 + (s.v1 - s.v0) * j / 16);
      lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    }
  shape.scale = (hi - lo).norm();
  if (!std::isfinite(shape.scale)) throw Error(ErrorCode::NonFinite, "the surface is not finite");
  seamOf(s, shape.scale, &shape.closed, &shape.periodic);
  *creases = findCreases(s, &shape.kinkAtEnds);
  shape.periodic = shape.periodic && creases->empty();
  return shape;
}

// The certificate's points for the current spans, a crease marked where a v-line lies on one
// (a seam that is closed but not smooth is one too).
CertificateGrid certificateGrid(const SpanSet& U, const SpanSet& V, const Shape& shape) {
  CertificateGrid grid;
  certificateLine(U, &grid.u, &grid.uSpan);
  certificateLine(V, &grid.v, &grid.vSpan);
  grid.vCrease.assign(grid.v.size(), false);
  for (size_t j = 0; j < grid.v.size(); ++j) {
    const size_t span = size_t(grid.vSpan[std::min(j, grid.vSpan.size() - 1)]);
    for (size_t b : {span, span + 1})
      if (V.crease[b] && grid.v[j] == V.breaks[b]) grid.vCrease[j] = true;
  }
  if ((shape.closed && !shape.periodic) || shape.kinkAtEnds) grid.vCrease.front() = grid.vCrease.back() = true;
  return grid;
}

Error limitsReached(double reached, const FitOptions& o, const FitReport& rep) {
  return Error(ErrorCode::TooLarge,
               "the fit reached a certified deviation of " + number(reached) + " (tolerance " + number(o.tolerance) +
                   "), normals within " + number(rep.normalDeviationDeg) + "° (" + number(o.normalToleranceDeg) + "°)" +
                   " (limits: " + std::to_string(kFitMaxSpans) + " spans per direction, " + std::to_string(kFitMaxGridPoints) +
                   " certificate points, " + std::to_string(kFitMaxIterations) + " refinements)");
}

}  // namespace

// Fit, certify, refine where the certificate fails, until the tolerance (and the normals'
// target) is met or a limit is reached; the best fit within the tolerance is kept.
BSplineSurface fitSurface(const SeparableSurface& s, const FitOptions& o, FitReport* report) {
  if (!(o.tolerance > 0) || !std::isfinite(o.tolerance))
    throw Error(ErrorCode::InvalidField, "tolerance: must be a positive finite number, not " + number(o.tolerance));
  if (o.degree != 3 && o.degree != 5) throw Error(ErrorCode::InvalidField, "degree: must be 3 or 5");
  FitReport rep;
  std::vector<double> creases;
  const Shape shape = shapeOf(s, &creases);
  rep.scale = shape.scale;
  rep.periodicV = shape.periodic;
  rep.creases = int(creases.size());
  SpanSet U = initialSpans(s.u0, s.u1, 4, 4, {}), V = initialSpans(s.v0, s.v1, shape.periodic ? 8 : 4, 4, creases);
  BSplineSurface best;
  double reached = HUGE_VAL;
  GeneralBoundCache boundCache;
  // The fit of the current spans, kept while only the certificate's cells are refined.
  LeastSquares fit;
  FourthBounds boundB;
  bool spansChanged = true;
  for (int iter = 1;; ++iter) {
    const CertificateGrid grid = certificateGrid(U, V, shape);
    const long points = long(grid.u.size()) * long(grid.v.size());
    if (iter > kFitMaxIterations || U.count() > kFitMaxSpans || V.count() > kFitMaxSpans || points > kFitMaxGridPoints) {
      // The tolerance is a promise; the normals' target is best effort: a fit within the
      // tolerance is kept and reports the normals it reached (normalsMet false).
      if (reached <= o.tolerance) break;
      throw limitsReached(reached, o, rep);
    }
    const SurfaceOnGrid surface(s, grid.u);
    // This round's point evaluations (five partials each for the certificate, three more for a
    // new least-squares fit), charged to the scene's budget before they are made.
    if (o.work) o.work->charge(double(points) * surface.pointCost() * (spansChanged ? 8 : 5));
    boundCache.work = o.work;
    if (spansChanged) {
      fit = leastSquares(s, o.degree, U, V, grid, fitData(s, surface, grid), shape);
      boundB = splineFourthBounds(fit.surface);
    }
    const BSplineSurface& b = fit.surface;
    const FourthBounds boundS = boundFourth(s, U.breaks, V.breaks, &boundCache);
    const Certificate cert = certify(grid, surface, b, boundS, boundB, o.tolerance, o.normalToleranceDeg);
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
    const RefinePlan plan = planRefinement({&U, &V, &grid, &cert, &fit.uResidual, &fit.vResidual, o.tolerance,
                                            o.normalToleranceDeg, o.degree, shape.periodic});
    spansChanged = plan.splitsSpans();
    applyPlan(U, plan.piecesU, plan.cutsU);
    applyPlan(V, plan.piecesV, plan.cutsV);
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
