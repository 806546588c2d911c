#include "bezier/interior_basis.hpp"

#include <vector>

namespace pdesurf {

namespace {
double binomial(int n, int k) {
  double c = 1.0;
  for (int j = 1; j <= k; ++j) c = c * (n - k + j) / j;
  return c;
}
}  // namespace

Eigen::MatrixXd interiorToBernstein(int n, int r) {
  const int count = n - 2 * r + 1;
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(n + 1, count);
  for (int k = 0; k < count; ++k) {
    // P_k(2u - 1) = Σ_i (-1)^{k+i} C(k, i) B_i^k; times (u(1-u))^r: B_i^k → C(k,i)/C(k+2r,i+r) B_{i+r}^{k+2r}.
    const int d0 = k + 2 * r;
    std::vector<double> c(d0 + 1, 0.0);
    for (int i = 0; i <= k; ++i) c[i + r] = ((k + i) % 2 ? -1.0 : 1.0) * binomial(k, i) * binomial(k, i) / binomial(d0, i + r);
    // Degree elevation d → d+1: c'_i = i/(d+1) c_{i-1} + (1 - i/(d+1)) c_i.
    for (int d = d0; d < n; ++d) {
      std::vector<double> e(d + 2);
      for (int i = 0; i <= d + 1; ++i) {
        const double a = static_cast<double>(i) / (d + 1);
        e[i] = (i > 0 ? a * c[i - 1] : 0.0) + (i <= d ? (1 - a) * c[i] : 0.0);
      }
      c.swap(e);
    }
    for (int i = 0; i <= n; ++i) T(i, k) = c[i];
  }
  return T;
}

}  // namespace pdesurf
