#include "pde/poly_in_v.hpp"

#include <Eigen/Dense>

namespace pdesurf {

namespace {

using Poly = std::vector<double>;  // ascending coefficients

Poly differentiate(const Poly& p, int times) {
  Poly q = p;
  for (int t = 0; t < times && !q.empty(); ++t) {
    for (size_t k = 1; k < q.size(); ++k) q[k - 1] = k * q[k];
    q.pop_back();
  }
  return q;
}

Poly integrate(const Poly& p, int times) {
  Poly q = p;
  for (int t = 0; t < times; ++t) {
    Poly r(q.size() + 1, 0.0);
    for (size_t k = 0; k < q.size(); ++k) r[k + 1] = q[k] / (k + 1);
    q.swap(r);
  }
  return q;
}

double evalDerivative(const Poly& p, int i, double u) {
  const Poly d = differentiate(p, i);
  double acc = 0.0;
  for (size_t k = d.size(); k-- > 0;) acc = acc * u + d[k];
  return acc;
}

double fallingFactorial(int top, int count) {
  double f = 1.0;
  for (int i = 0; i < count; ++i) f *= top - i;
  return f;
}

// Inverse of the Hermite matrix of u^0..u^{2n-1} (rows: end, derivative order), per n, built
// once: it is the same for every solve.
const Eigen::MatrixXd& hermiteInverse(int n) {
  thread_local std::vector<Eigen::MatrixXd> cache;  // per thread: the CLI fits patches on several
  if (static_cast<int>(cache.size()) <= n) cache.resize(n + 1);
  Eigen::MatrixXd& inv = cache[n];
  if (inv.size() == 0) {
    Eigen::MatrixXd h(2 * n, 2 * n);
    for (int end = 0; end < 2; ++end)
      for (int i = 0; i < n; ++i)
        for (int k = 0; k < 2 * n; ++k) {
          Poly mono(k + 1, 0.0);
          mono[k] = 1.0;
          h(end * n + i, k) = evalDerivative(mono, i, end);
        }
    inv = h.fullPivLu().inverse();
  }
  return inv;
}

}  // namespace

std::vector<std::vector<double>> solvePolyInV(const std::vector<double>& alpha,
                                              const std::vector<std::vector<std::vector<double>>>& data,
                                              const std::vector<std::vector<double>>& force) {
  const int n = static_cast<int>(alpha.size()) - 1;
  const int top = static_cast<int>(data.size()) - 1;
  const Eigen::MatrixXd& hermite = hermiteInverse(n);

  std::vector<Poly> g(top + 1);
  for (int m = top; m >= 0; --m) {
    Poly rhs;
    if (m < static_cast<int>(force.size()))
      for (double c : force[m]) rhs.push_back(c / alpha[0]);
    for (int j = 1; j <= n && m + 2 * j <= top; ++j) {
      const Poly d = differentiate(g[m + 2 * j], 2 * n - 2 * j);
      const double factor = -alpha[j] * fallingFactorial(m + 2 * j, 2 * j) / alpha[0];
      if (rhs.size() < d.size()) rhs.resize(d.size(), 0.0);
      for (size_t k = 0; k < d.size(); ++k) rhs[k] += factor * d[k];
    }
    Poly particular = rhs.empty() ? Poly{} : integrate(rhs, 2 * n);
    Eigen::VectorXd b(2 * n);
    for (int end = 0; end < 2; ++end)
      for (int i = 0; i < n; ++i) b(end * n + i) = data[m][end][i] - evalDerivative(particular, i, end);
    const Eigen::VectorXd c = hermite * b;
    if (particular.size() < static_cast<size_t>(2 * n)) particular.resize(2 * n, 0.0);
    for (int k = 0; k < 2 * n; ++k) particular[k] += c(k);
    g[m] = particular;
  }
  return g;
}

}  // namespace pdesurf
