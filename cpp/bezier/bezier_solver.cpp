#include "bezier/bezier_solver.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "bezier/bezier_assembly.hpp"
#include "bezier/interior_basis.hpp"
#include "common/errors.hpp"
#include "common/text.hpp"

namespace pdesurf {

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// Q(3k + c, 3l + c) += scale S(k, l) for c = 0, 1, 2 (column by column: Eigen is column-major).
void addBlockDiagonal(MatrixXd& Q, const MatrixXd& S, double scale) {
  for (int l = 0; l < S.cols(); ++l)
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < S.rows(); ++k) Q(3 * k + c, 3 * l + c) += scale * S(k, l);
}

// A singular system shows zero or negative pivots; positive ones are accepted down to 1e-16 of
// the largest.
bool pivotsOk(const Eigen::LDLT<MatrixXd>& ldlt) {
  const VectorXd D = ldlt.vectorD();
  return ldlt.info() == Eigen::Success && D.minCoeff() > 1e-16 * std::max(1.0, D.maxCoeff());
}

void requireFinite(const Eigen::Vector3d& p, const std::string& what) {
  if (!p.allFinite()) throw Error(ErrorCode::NonFinite, what + " is not finite");
}

}  // namespace

void validateBezierProblem(const BezierProblem& p) {
  const bool thin = p.energy == BezierEnergy::ThinPlate;
  const int need = thin ? 4 : 2;
  if (p.n < need || p.m < need)
    throw Error(ErrorCode::InvalidField, std::string("degree ") + std::to_string(p.n) + "x" + std::to_string(p.m) + " leaves no free control point: the " +
                                             (thin ? "thin-plate energy fixes two rings and needs degree 4x4 or more"
                                                   : "membrane energy fixes one ring and needs degree 2x2 or more"));
  if (p.n > 16 || p.m > 16) throw Error(ErrorCode::InvalidField, "degree above 16x16 (17x17 control points): the Bernstein basis is too ill-conditioned");
  if (static_cast<int>(p.initial.size()) != (p.n + 1) * (p.m + 1))
    throw Error(ErrorCode::InvalidField, "the control net needs " + std::to_string((p.n + 1) * (p.m + 1)) + " points");
  for (size_t k = 0; k < p.initial.size(); ++k) requireFinite(p.initial[k], "control point " + std::to_string(k));
  if (!std::isfinite(p.lambda) || p.lambda < 0) throw Error(ErrorCode::InvalidField, "lambda must be a finite number >= 0");
  if (!std::isfinite(p.gamma) || p.gamma < 0) throw Error(ErrorCode::InvalidField, "gamma must be a finite number >= 0");
  const BezierNormalField& f = p.normals;
  const size_t count = f.discrete ? static_cast<size_t>(f.np + 1) * (f.mp + 1) : static_cast<size_t>(f.n1 + 1) * (f.m1 + 1);
  if (f.discrete && (f.np < 1 || f.mp < 1 || f.np > 256 || f.mp > 256))
    throw Error(ErrorCode::InvalidField, "the normal sample grid must be 1x1 .. 256x256");
  if (!f.discrete && (f.n1 < 0 || f.m1 < 0 || f.n1 > 24 || f.m1 > 24))
    throw Error(ErrorCode::InvalidField, "the normal field's degree must be 0x0 .. 24x24");
  if (f.vectors.size() != count) throw Error(ErrorCode::InvalidField, "the normal field needs " + std::to_string(count) + " vectors");
  for (size_t k = 0; k < f.vectors.size(); ++k) {
    requireFinite(f.vectors[k], "normal " + std::to_string(k));
    if (f.vectors[k].norm() < 1e-12) throw Error(ErrorCode::InvalidField, "normal " + std::to_string(k) + " has zero length");
    // A continuous field is the Bézier vector function as given (its length weighs λ, as in
    // Eqs. 1-2); past a float's range squared it is no weight at all.
    if (!f.discrete && !std::isfinite(p.lambda * f.vectors[k].squaredNorm()))
      throw Error(ErrorCode::NonFinite, "normal " + std::to_string(k) + " is " + numberText(f.vectors[k].stableNorm()) +
                                            " long: lambda times its length squared is not finite (a continuous field's length weighs lambda)");
  }
  for (const auto* w : {&f.lambdaWeight, &f.gammaWeight}) {
    if (!w->empty() && w->size() != count) throw Error(ErrorCode::InvalidField, "per-sample weights need " + std::to_string(count) + " values");
    for (double x : *w)
      if (!std::isfinite(x) || x < 0) throw Error(ErrorCode::InvalidField, "per-sample weights must be finite and >= 0");
  }
}

BezierSolver::BezierSolver(const BezierProblem& shape) : shape_(shape) {
  validateBezierProblem(shape_);
  const int n = shape_.n, m = shape_.m, K = (n + 1) * (m + 1);
  // Fairness: always the exact integral. The normal and data terms: the exact integral for a
  // continuous field or, for a discrete one, the samples with trapezoidal weights (summing to
  // 1, like the integral) times the per-sample weights. Seed 002's Eq. 5 sums every term,
  // fairness included, with unit weights; that biased sum pins the surface only loosely (a
  // flat square comes back with its control net 2.4 off the grid), so pdesurf keeps the
  // fairness exact. The matrices come from the tensor-product assembly (bezier_assembly.hpp).
  BezierForms forms = assembleBezierForms(shape_);
  normal_ = std::move(forms.normal);
  const MatrixXd& F = forms.fairness;
  const MatrixXd& mass = forms.mass;

  Q_ = shape_.lambda * normal_;
  addBlockDiagonal(Q_, F, 1.0);
  addBlockDiagonal(Q_, mass, shape_.gamma);
  G_ = MatrixXd::Zero(3 * K, 3 * K);
  addBlockDiagonal(G_, mass, shape_.gamma);

  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j)
      for (int c = 0; c < 3; ++c) (shape_.isFixed(i, j) ? fixed_ : free_).push_back(3 * shape_.index(i, j) + c);
  const int nf = static_cast<int>(free_.size()), nx = static_cast<int>(fixed_.size());
  MatrixXd Qff(nf, nf);
  Qfx_.resize(nf, nx);
  Gf_.resize(nf, 3 * K);
  // Gathered column by column (Eigen is column-major).
  for (int b = 0; b < nf; ++b)
    for (int a = 0; a < nf; ++a) Qff(a, b) = Q_(free_[a], free_[b]);
  for (int b = 0; b < nx; ++b)
    for (int a = 0; a < nf; ++a) Qfx_(a, b) = Q_(free_[a], fixed_[b]);
  for (int b = 0; b < 3 * K; ++b)
    for (int a = 0; a < nf; ++a) Gf_(a, b) = G_(free_[a], b);
  ldlt_.compute(Qff);
  // Bernstein bases are badly conditioned at high degree (a 16×16 net's smallest pivot is
  // ~5e-14 of its largest), yet the surface they span is well determined. Where the pivots
  // fail (degree 16 membrane with γ ≥ 1e4: the rounded matrix is indefinite), the free block
  // is assembled again in a well-conditioned basis of the same space (interior_basis.hpp);
  // only if that fails too is the energy singular (the fairness drowned by λ, say).
  if (!pivotsOk(ldlt_)) factorInInteriorBasis();
}

void BezierSolver::factorInInteriorBasis() {
  const int n = shape_.n, m = shape_.m, r = shape_.energy == BezierEnergy::ThinPlate ? 2 : 1;
  const MatrixXd Tu = interiorToBernstein(n, r), Tv = interiorToBernstein(m, r);
  const BezierForms b = assembleBezierForms(shape_, &Tu, &Tv);
  MatrixXd Qb = shape_.lambda * b.normal;
  addBlockDiagonal(Qb, b.fairness, 1.0);
  addBlockDiagonal(Qb, b.mass, shape_.gamma);
  // x_free = Tfree y: free coordinate (i, j, c) = Σ_kl Tu(i, k) Tv(j, l) y(k, l, c).
  const int mb = static_cast<int>(Tv.cols()) - 1;
  Tfree_ = MatrixXd::Zero(free_.size(), Qb.rows());
  for (size_t a = 0; a < free_.size(); ++a) {
    const int point = free_[a] / 3, c = free_[a] % 3, i = point / (m + 1), j = point % (m + 1);
    for (int k = 0; k < Tu.cols(); ++k)
      for (int l = 0; l <= mb; ++l) Tfree_(a, 3 * (k * (mb + 1) + l) + c) = Tu(i, k) * Tv(j, l);
  }
  ldlt_.compute(Qb);
  if (!pivotsOk(ldlt_))
    throw Error(ErrorCode::Singular, "the energy has no unique minimiser (its matrix is singular to working precision): "
                                     "reduce lambda or gamma, or the degree");
}

ControlNet BezierSolver::solve(const ControlNet& initial) const {
  const int K = (shape_.n + 1) * (shape_.m + 1);
  if (static_cast<int>(initial.size()) != K) throw Error(ErrorCode::InvalidField, "the control net needs " + std::to_string(K) + " points");
  VectorXd s(3 * K);
  for (int k = 0; k < K; ++k) {
    requireFinite(initial[k], "control point " + std::to_string(k));
    s.segment<3>(3 * k) = initial[k];
  }
  VectorXd xFixed(fixed_.size());
  for (size_t b = 0; b < fixed_.size(); ++b) xFixed(b) = s(fixed_[b]);
  const VectorXd rhs = Gf_ * s - Qfx_ * xFixed;
  const VectorXd xFree = Tfree_.size() ? VectorXd(Tfree_ * ldlt_.solve(Tfree_.transpose() * rhs)) : VectorXd(ldlt_.solve(rhs));
  if (!xFree.allFinite()) throw Error(ErrorCode::Singular, "the solve produced non-finite control points");
  ControlNet out = initial;  // fixed rings stay exactly as given
  for (size_t a = 0; a < free_.size(); ++a) out[free_[a] / 3](free_[a] % 3) = xFree(a);
  return out;
}

double BezierSolver::energy(const ControlNet& net, const ControlNet& initial) const {
  const int K = (shape_.n + 1) * (shape_.m + 1);
  VectorXd x(3 * K), s(3 * K);
  for (int k = 0; k < K; ++k) x.segment<3>(3 * k) = net[k], s.segment<3>(3 * k) = initial[k];
  // ½ xᵀQx - (Gs)ᵀx + ½ sᵀGs = ½ fairness + ½ λ normal + ½ γ |x - s|²_M
  return 0.5 * x.dot(Q_ * x) - x.dot(G_ * s) + 0.5 * s.dot(G_ * s);
}

double BezierSolver::normalMisfit(const ControlNet& net) const {
  const int K = (shape_.n + 1) * (shape_.m + 1);
  VectorXd x(3 * K);
  for (int k = 0; k < K; ++k) x.segment<3>(3 * k) = net[k];
  return x.dot(normal_ * x);
}

ControlNet solveBezier(const BezierProblem& p) { return BezierSolver(p).solve(p.initial); }

SeparableSurface bezierToSeparable(int n, int m, const ControlNet& net) {
  // R = Σ_j (Σ_i P_ij B_i^n(u)) B_j^m(v): per coordinate and column j, a Bernstein-form
  // u-factor times the basis function B_j^m(v), both evaluated in Bernstein form.
  SeparableSurface s;
  s.u0 = 0, s.u1 = 1, s.v0 = 0, s.v1 = 1;
  for (int c = 0; c < 3; ++c)
    for (int j = 0; j <= m; ++j) {
      std::vector<double> column(n + 1);
      for (int i = 0; i <= n; ++i) column[i] = net[i * (m + 1) + j](c);
      VFunction g;
      g.family = Family::Bernstein;
      g.n = j;
      g.degree = m;
      s.component[c].push_back({g, UFactor::bernsteinForm(column)});
    }
  return s;
}

}  // namespace pdesurf
