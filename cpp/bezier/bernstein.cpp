#include "bezier/bernstein.hpp"

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <string>

#include "common/errors.hpp"

namespace pdesurf {

// d^k B_i^n = n!/(n-k)! Σ_j (-1)^{k-j} C(k, j) B_{i-j}^{n-k}: the forward differences of the
// unit vector e_i, which have at most k + 1 non-zero entries. low[] = B^{n-k}(u).
double bernsteinBasisFrom(const double* low, int n, int i, int k) {
  double s = 0.0, ckj = 1.0, scale = 1.0;
  for (int q = 0; q < k; ++q) scale *= n - q;
  for (int j = 0; j <= k; ++j) {
    const int idx = i - j;
    if (idx >= 0 && idx <= n - k) s += ((k - j) % 2 ? -1.0 : 1.0) * ckj * low[idx];
    ckj = ckj * (k - j) / (j + 1);
  }
  return scale * s;
}

const double* BernsteinOnGrid::values(int n) {
  if (static_cast<int>(byDegree_.size()) <= n) byDegree_.resize(n + 1);
  std::vector<double>& v = byDegree_[n];
  if (v.empty()) {
    v.resize(static_cast<size_t>(count_) * (n + 1));
    for (int i = 0; i < count_; ++i) bernsteinValues(n, t_[i], v.data() + static_cast<size_t>(i) * (n + 1));
  }
  return v.data();
}

std::vector<double> bernstein(int n, double u, int k) {
  std::vector<double> out(n + 1, 0.0);
  if (k > n) return out;
  std::array<double, kMaxBernsteinDegree + 1> low;
  bernsteinValues(n - k, u, low.data());
  for (int i = 0; i <= n; ++i) out[i] = bernsteinBasisFrom(low.data(), n, i, k);
  return out;
}

void bernsteinValues(int n, double u, double* out) {
  if (n < 0 || n > kMaxBernsteinDegree) throw Error(ErrorCode::Internal, "Bernstein degree " + std::to_string(n) + " is out of range");
  // out[i] = C(n,i) u^i (1-u)^{n-i}: u^i from the left, (1-u)^{n-i} from the right.
  const double w = 1.0 - u;
  double p = 1.0;
  for (int i = 0; i <= n; ++i) out[i] = p, p *= u;
  p = 1.0;
  double c = 1.0;  // C(n, i), exact in double for n <= 32
  for (int i = n; i >= 0; --i) {
    out[i] *= p;
    p *= w;
  }
  for (int i = 0; i <= n; ++i) {
    out[i] *= c;
    c = c * (n - i) / (i + 1);
  }
}

std::vector<double> bernsteinDerivativeCoefs(const std::vector<double>& b, int k) {
  const int n = static_cast<int>(b.size()) - 1;
  if (k > n) return {};
  std::vector<double> d = b;
  double scale = 1.0;
  for (int q = 0; q < k; ++q) {
    for (size_t i = 0; i + 1 < d.size(); ++i) d[i] = d[i + 1] - d[i];
    d.pop_back();
    scale *= n - q;
  }
  for (double& x : d) x *= scale;
  return d;
}

double bernsteinSum(const double* b, int n, double u) {
  std::array<double, kMaxBernsteinDegree + 1> B;
  bernsteinValues(n, u, B.data());
  double s = 0.0;
  for (int i = 0; i <= n; ++i) s += b[i] * B[i];
  return s;
}

double bernsteinBasis(int n, int i, double u, int k) {
  if (k > n || i < 0 || i > n) return 0.0;
  std::array<double, kMaxBernsteinDegree + 1> low;
  bernsteinValues(n - k, u, low.data());
  return bernsteinBasisFrom(low.data(), n, i, k);
}

GaussRule gaussLegendre(int points) {
  // Golub-Welsch: eigenvalues of the Jacobi matrix are the nodes on [-1, 1].
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(points, points);
  for (int k = 1; k < points; ++k) J(k, k - 1) = J(k - 1, k) = k / std::sqrt(4.0 * k * k - 1);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(J);
  GaussRule rule;
  for (int k = 0; k < points; ++k) {
    rule.x.push_back(0.5 * (es.eigenvalues()(k) + 1));
    const double v0 = es.eigenvectors()(0, k);
    rule.w.push_back(v0 * v0);  // weights on [-1,1] are 2 v0², halved for [0, 1]
  }
  return rule;
}

}  // namespace pdesurf
