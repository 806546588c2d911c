#include "bezier/bernstein.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace pdesurf {

namespace {
double binomial(int n, int k) {
  double r = 1.0;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}
}  // namespace

std::vector<double> bernstein(int n, double u, int k) {
  std::vector<double> out(n + 1, 0.0);
  if (k > n) return out;
  // d^k B_i^n = n!/(n-k)! Σ_j (-1)^{k-j} C(k, j) B_{i-j}^{n-k}
  const int d = n - k;
  std::vector<double> low(d + 1);
  for (int i = 0; i <= d; ++i) low[i] = binomial(d, i) * std::pow(u, i) * std::pow(1 - u, d - i);
  double scale = 1.0;
  for (int q = 0; q < k; ++q) scale *= n - q;
  for (int i = 0; i <= n; ++i) {
    double s = 0.0;
    for (int j = 0; j <= k; ++j) {
      const int idx = i - j;
      if (idx < 0 || idx > d) continue;
      s += ((k - j) % 2 ? -1.0 : 1.0) * binomial(k, j) * low[idx];
    }
    out[i] = scale * s;
  }
  return out;
}

std::vector<std::vector<double>> bernsteinMonomials(int n) {
  // B_i^n = C(n,i) u^i (1-u)^{n-i} = C(n,i) Σ_r C(n-i, r) (-1)^r u^{i+r}
  std::vector<std::vector<double>> out(n + 1, std::vector<double>(n + 1, 0.0));
  for (int i = 0; i <= n; ++i)
    for (int r = 0; r <= n - i; ++r) out[i][i + r] = binomial(n, i) * binomial(n - i, r) * (r % 2 ? -1.0 : 1.0);
  return out;
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
