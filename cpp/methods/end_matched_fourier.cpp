// Open data (f on [v0, v1] with f(v0) != f(v1)) for the modal method. A truncated Fourier
// series of f itself converges slowly (its periodic extension jumps), and a Chebyshev
// interpolant in powers of v cannot go past degree ~20 (the closed form multiplies its tiny
// high coefficients by factorials). So: p, the Hermite interpolant of degree 2m+1 that matches
// f and its first m derivatives at both ends, carries the ends, and the rest g = f - p, whose
// derivatives up to m vanish at both ends, extends periodically with m continuous
// derivatives: its Fourier coefficients fall like k^-(m+2), with as many modes as wanted
// (Eckhoff's method, in the form of Lanczos' and Krylov's polynomial subtraction).
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <vector>
#include <cmath>

#include "common/errors.hpp"
#include "common/text.hpp"
#include "methods/approximate.hpp"

namespace pdesurf {

VExpansion endMatchedFourier(const VExpansion& f, double v0, double v1, int N, int m) {
  const double c = 0.5 * (v0 + v1), w = 2.0 / (v1 - v0);  // s = (v - c) w runs over [-1, 1]
  // d^k f / ds^k at both ends; where a derivative is not finite (f ~ sqrt(v - v0) at an end)
  // match one order less: the series then converges more slowly, but converges.
  std::array<std::vector<double>, 2> ends;
  for (int end = 0; end < 2; ++end)
    for (int k = 0; k <= m; ++k) {
      const double d = expansionValue(f, end ? v1 : v0, k) / std::pow(w, k);
      if (!std::isfinite(d)) {
        if (k == 0)
          throw Error(ErrorCode::NonFinite, "'" + (f.empty() ? std::string("?") : describeFunction(f.front().g)) +
                                                "' is not finite at v = " + numberText(end ? v1 : v0));
        m = k - 1;
        break;
      }
      ends[end].push_back(d);
    }
  const int rows = 2 * m + 2;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(rows, rows);
  Eigen::VectorXd b(rows);
  for (int end = 0; end < 2; ++end) {
    const double s = end ? 1.0 : -1.0;
    for (int k = 0; k <= m; ++k) {
      const int row = end * (m + 1) + k;
      for (int j = k; j < rows; ++j) {
        double falling = 1.0;  // d^k/ds^k s^j = j!/(j-k)! s^{j-k}
        for (int i = 0; i < k; ++i) falling *= j - i;
        A(row, j) = falling * std::pow(s, j - k);
      }
      b(row) = ends[end][k];
    }
  }
  const Eigen::VectorXd coef = A.fullPivLu().solve(b);
  VExpansion poly, rest = f;
  for (int j = 0; j < rows; ++j) {
    VFunction g{Family::Poly, w, j};
    g.c = c;
    poly.push_back({g, coef(j)});
    rest.push_back({g, -coef(j)});
  }
  // f - p cancels: its samples carry the rounding of the larger of the two.
  double scale = 0.0;
  for (int j = 0; j <= 256; ++j) {
    const double v = v0 + (v1 - v0) * j / 256;
    scale = std::max({scale, std::abs(expansionValue(f, v)), std::abs(expansionValue(poly, v))});
  }
  VExpansion out = fourierSeries(rest, v0, v1, N, 1e-15 * scale, true);
  out.insert(out.end(), poly.begin(), poly.end());
  return out;
}

}  // namespace pdesurf
