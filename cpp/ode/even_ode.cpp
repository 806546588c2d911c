#include "ode/even_ode.hpp"

#include <cmath>
#include <numeric>

#include "common/text.hpp"
#include "common/errors.hpp"

namespace pdesurf {

namespace {

// Roots of a polynomial with complex-capable output; coefficients in descending powers,
// leading coefficient non-zero. Degrees 1 and 2 in closed form, higher by the companion
// matrix.
std::vector<cplx> polyRoots(const std::vector<double>& desc) {
  const int deg = static_cast<int>(desc.size()) - 1;
  std::vector<cplx> out;
  if (deg == 1) {
    out.push_back(-desc[1] / desc[0]);
  } else if (deg == 2) {
    const double a = desc[0], b = desc[1], c = desc[2];
    const cplx disc = std::sqrt(cplx(b * b - 4 * a * c));
    // Stable form: avoid cancellation between -b and the root of the discriminant.
    const cplx q = -0.5 * (b >= 0 ? cplx(b) + disc : cplx(b) - disc);
    if (q == 0.0) {
      out.push_back(0.0);
      out.push_back(0.0);
    } else {
      out.push_back(q / a);
      out.push_back(c / q);
    }
  } else if (deg > 2) {
    Eigen::MatrixXd comp = Eigen::MatrixXd::Zero(deg, deg);
    for (int k = 0; k < deg; ++k) comp(0, k) = -desc[k + 1] / desc[0];
    for (int k = 1; k < deg; ++k) comp(k, k - 1) = 1.0;
    Eigen::EigenSolver<Eigen::MatrixXd> es(comp, false);
    if (es.info() != Eigen::Success) throw Error(ErrorCode::Internal, "eigenvalue solver failed on the characteristic polynomial");
    for (int k = 0; k < deg; ++k) out.push_back(es.eigenvalues()[k]);
  }
  return out;
}

}  // namespace

std::vector<cplx> characteristicRoots(const std::vector<double>& alpha, double sigma) {
  const int n = static_cast<int>(alpha.size()) - 1;
  // rho = |sigma| mu keeps the coefficients of the polynomial in mu of order one.
  const double scale = std::abs(sigma);
  const double sign = sigma < 0 ? -1.0 : 1.0;
  std::vector<double> desc(n + 1);
  double s = 1.0;
  for (int k = 0; k <= n; ++k) {
    desc[k] = scale == 0.0 ? (k == 0 ? alpha[0] : 0.0) : alpha[k] * s;
    s *= sign;
  }
  // Exact zero roots (sigma = 0, or vanishing trailing coefficients) are taken out exactly.
  int zeros = 0;
  while (desc.size() > 1 && desc.back() == 0.0) {
    desc.pop_back();
    ++zeros;
  }
  std::vector<cplx> rho(zeros, 0.0);
  for (cplx m : polyRoots(desc)) rho.push_back(m * scale);
  std::vector<cplx> r;
  for (cplx p : rho) {
    const cplx q = std::sqrt(p);
    r.push_back(q);
    r.push_back(-q);
  }
  return r;
}

EvenOdeBasis::EvenOdeBasis(const std::vector<double>& alpha, double sigma, int forceDegree) {
  n_ = static_cast<int>(alpha.size()) - 1;
  extra_ = std::max(0, forceDegree + 1);
  if (n_ < 1) throw Error(ErrorCode::InvalidField, "operator needs at least two coefficients");
  for (double a : alpha)
    if (!std::isfinite(a)) throw Error(ErrorCode::NonFinite, "operator coefficient is not finite");
  if (alpha[0] == 0.0)
    throw Error(ErrorCode::DegenerateOperator, "the coefficient of the highest u-derivative is 0: the PDE loses its order in u");
  if (!std::isfinite(sigma)) throw Error(ErrorCode::NonFinite, "frequency is not finite");
  roots_ = characteristicRoots(alpha, sigma);
  const int ownRoots = static_cast<int>(roots_.size());
  roots_.insert(roots_.end(), extra_, cplx(0.0));

  // Group roots closer than one unit (single linkage).
  const int m = static_cast<int>(roots_.size());
  std::vector<int> group(m);
  std::iota(group.begin(), group.end(), 0);
  auto find = [&](int i) {
    while (group[i] != i) i = group[i] = group[group[i]];
    return i;
  };
  for (int i = 0; i < m; ++i)
    for (int j = i + 1; j < m; ++j)
      if (std::abs(roots_[i] - roots_[j]) < 1.0) group[find(i)] = find(j);

  constexpr int kSeries = 60;  // divided-difference series length: |delta| <= 5 leaves < 1e-38
  for (int g = 0; g < m; ++g) {
    if (find(g) != g) continue;
    std::vector<cplx> members;
    Cluster cl;
    for (int i = 0; i < m; ++i)
      if (find(i) == g) {
        members.push_back(roots_[i]);
        cl.augmented = cl.augmented || i >= ownRoots;
      }
    cl.centre = std::accumulate(members.begin(), members.end(), cplx(0.0)) / static_cast<double>(members.size());
    cl.shift = cl.centre.real() > 0 ? 1.0 : 0.0;
    const int p = static_cast<int>(members.size());
    std::vector<cplx> delta(p);
    bool allZero = true;
    for (int i = 0; i < p; ++i) {
      delta[i] = members[i] - cl.centre;
      if (delta[i] != 0.0) allZero = false;
    }
    const int terms = allZero ? p : kSeries;
    // h[m] = complete homogeneous symmetric polynomial of degree m in delta_1..delta_q.
    std::vector<cplx> h(terms, 0.0);
    h[0] = 1.0;  // q = 0
    std::vector<double> invFact(terms, 1.0);
    for (int k = 1; k < terms; ++k) invFact[k] = invFact[k - 1] / k;
    for (int j = 0; j < p; ++j) {
      for (int k = 1; k < terms; ++k) h[k] += delta[j] * h[k - 1];  // add delta_{j+1}
      // q_j(x) = Σ_{k>=j} h_{k-j}(delta_1..delta_{j+1}) x^k / k!
      std::vector<cplx> q(terms, 0.0);
      for (int k = j; k < terms; ++k) q[k] = h[k - j] * invFact[k];
      double biggest = 0.0;
      for (const cplx& c : q) biggest = std::max(biggest, std::abs(c));
      while (q.size() > static_cast<size_t>(j + 1) && std::abs(q.back()) < 1e-40 * biggest) q.pop_back();
      cl.basis.push_back(q);
    }
    clusters_.push_back(std::move(cl));
  }

  // Rows: the 2n boundary conditions (end, derivative order), then the extra_ force rows
  // (L G)^{(i)}(0). Columns: (cluster, basis function). L annihilates every function of a
  // cluster made only of L's own roots, so those entries are exactly 0, not roundoff.
  std::vector<double> gamma(n_ + 1);  // gamma[m] multiplies the 2m-th derivative
  for (int k = 0; k <= n_; ++k) gamma[n_ - k] = alpha[k] * std::pow(sigma, k);
  const int size = 2 * n_ + extra_;
  if (size > kMaxBoundarySystem) throw Error(ErrorCode::InvalidField, "force polynomial of too high a degree");
  BoundaryMatrix a = BoundaryMatrix::Zero(size, size);
  int col = 0;
  for (const Cluster& cl : clusters_) {
    for (const auto& q : cl.basis) {
      for (int end = 0; end < 2; ++end) {
        const double x = end - cl.shift;
        const cplx e = std::exp(cl.centre * x);
        for (int d = 0; d < n_; ++d) a(end * n_ + d, col) = e * evalPoly(derivativePoly(q, cl.centre, d), cplx(x));
      }
      if (cl.augmented) {
        const double x = -cl.shift;
        const cplx e = std::exp(cl.centre * x);
        for (int i = 0; i < extra_; ++i) {
          cplx sum = 0.0;
          for (int mm = 0; mm <= n_; ++mm)
            if (gamma[mm] != 0.0) sum += gamma[mm] * evalPoly(derivativePoly(q, cl.centre, 2 * mm + i), cplx(x));
          a(2 * n_ + i, col) = e * sum;
        }
      }
      ++col;
    }
  }
  // Equilibrate: derivative rows grow like |r|^d, basis columns differ in scale.
  rowScale_ = a.cwiseAbs().rowwise().maxCoeff().cwiseInverse();
  a = rowScale_.asDiagonal() * a;
  colScale_ = a.cwiseAbs().colwise().maxCoeff().cwiseInverse().transpose();
  a = a * colScale_.asDiagonal();
  if (!rowScale_.allFinite() || !colScale_.allFinite())
    throw Error(ErrorCode::Singular, "the boundary-value problem has no unique solution (a zero row or column)");
  lu_.compute(a);
  const double rcond = lu_.rcond();
  if (!(rcond > 1e-13))
    throw Error(ErrorCode::Singular, "the boundary-value problem has no unique solution: the parameters are resonant (rcond " +
                                         numberText(rcond) + ")");
}

UFactor EvenOdeBasis::solve(const double* left, const double* right, const std::vector<double>& force) const {
  if (static_cast<int>(force.size()) > extra_) throw Error(ErrorCode::Internal, "force degree above the basis's");
  BoundaryVector rhs = BoundaryVector::Zero(2 * n_ + extra_);
  for (int d = 0; d < n_; ++d) {
    rhs(d) = left[d];
    rhs(n_ + d) = right[d];
  }
  double factorial = 1.0;  // q^{(i)}(0) = i! q_i
  for (size_t i = 0; i < force.size(); ++i) {
    if (i > 0) factorial *= static_cast<double>(i);
    rhs(2 * n_ + i) = factorial * force[i];
  }
  const BoundaryVector amp = colScale_.asDiagonal() * lu_.solve(BoundaryVector(rowScale_.asDiagonal() * rhs));
  UFactor f;
  int col = 0;
  for (const Cluster& cl : clusters_) {
    ExpPoly piece;
    piece.rate = cl.centre;
    piece.shift = cl.shift;
    for (const auto& q : cl.basis) {
      if (piece.poly.size() < q.size()) piece.poly.resize(q.size(), 0.0);
      for (size_t k = 0; k < q.size(); ++k) piece.poly[k] += amp(col) * q[k];
      ++col;
    }
    f.pieces.push_back(std::move(piece));
  }
  return f;
}

}  // namespace pdesurf
