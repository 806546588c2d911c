#include "ode/u_factor.hpp"

#include <algorithm>
#include <array>

#include "bezier/bernstein.hpp"

namespace pdesurf {

std::vector<cplx> derivativePoly(const std::vector<cplx>& p, cplx rate, int m) {
  std::vector<cplx> q = p;
  for (int step = 0; step < m; ++step) {
    std::vector<cplx> next(q.size(), 0.0);
    for (size_t k = 0; k < q.size(); ++k) {
      next[k] += rate * q[k];
      if (k > 0) next[k - 1] += static_cast<double>(k) * q[k];
    }
    q.swap(next);
  }
  return q;
}

cplx evalPoly(const std::vector<cplx>& p, cplx x) {
  cplx acc = 0.0;
  for (size_t k = p.size(); k-- > 0;) acc = acc * x + p[k];
  return acc;
}

UFactor UFactor::polynomial(const std::vector<double>& ascending) {
  UFactor f;
  ExpPoly piece;
  piece.poly.assign(ascending.begin(), ascending.end());
  f.pieces.push_back(piece);
  return f;
}

UFactor UFactor::bernsteinForm(const std::vector<double>& coefs) {
  UFactor f;
  f.bernstein = coefs;
  return f;
}

double UFactor::eval(double u, int m) const {
  if (!bernstein.empty()) {
    const std::vector<double> d = bernsteinDerivativeCoefs(bernstein, m);
    return d.empty() ? 0.0 : bernsteinSum(d.data(), static_cast<int>(d.size()) - 1, u);
  }
  double sum = 0.0;
  for (const ExpPoly& piece : pieces) {
    const double x = u - piece.shift;
    const std::vector<cplx> q = derivativePoly(piece.poly, piece.rate, m);
    const cplx e = piece.rate == 0.0 ? cplx(1.0) : std::exp(piece.rate * x);
    sum += (e * evalPoly(q, x)).real();
  }
  return sum;
}

const cplx* ExpOnGrid::values(cplx rate, double shift) {
  auto [it, fresh] = kept_.try_emplace({{rate.real(), rate.imag()}, shift});
  if (fresh) {
    it->second.resize(static_cast<size_t>(count_));
    for (int i = 0; i < count_; ++i) it->second[size_t(i)] = std::exp(rate * (u_[i] - shift));
  }
  return it->second.data();
}

void UFactor::tabulate(const double* u, int count, int maxDerivative, double* out, BernsteinOnGrid* basis, ExpOnGrid* exps) const {
  std::fill(out, out + static_cast<size_t>(count) * (maxDerivative + 1), 0.0);
  if (!bernstein.empty()) {
    // Derivative coefficients once; per point the basis values of each lower degree.
    std::vector<std::vector<double>> d(maxDerivative + 1);
    for (int m = 0; m <= maxDerivative; ++m) d[m] = bernsteinDerivativeCoefs(bernstein, m);
    std::array<double, kMaxBernsteinDegree + 1> own;
    for (int m = 0; m <= maxDerivative; ++m) {
      if (d[m].empty()) continue;
      const int n = static_cast<int>(d[m].size()) - 1;
      const double* table = basis ? basis->values(n) : nullptr;
      for (int i = 0; i < count; ++i) {
        const double* B = table ? table + static_cast<size_t>(i) * (n + 1) : own.data();
        if (!table) bernsteinValues(n, u[i], own.data());
        double s = 0.0;
        for (int k = 0; k <= n; ++k) s += d[m][k] * B[k];
        out[static_cast<size_t>(m) * count + i] = s;
      }
    }
    return;
  }
  std::vector<std::vector<cplx>> q(maxDerivative + 1);
  for (const ExpPoly& piece : pieces) {
    for (int m = 0; m <= maxDerivative; ++m) q[m] = derivativePoly(piece.poly, piece.rate, m);
    const bool realPoly = piece.rate == 0.0;
    const cplx* kept = exps && !realPoly ? exps->values(piece.rate, piece.shift) : nullptr;
    for (int i = 0; i < count; ++i) {
      const double x = u[i] - piece.shift;
      if (realPoly) {
        for (int m = 0; m <= maxDerivative; ++m) {
          double acc = 0.0;
          for (size_t k = q[m].size(); k-- > 0;) acc = acc * x + q[m][k].real();
          out[static_cast<size_t>(m) * count + i] += acc;
        }
      } else {
        // x is real: Horner in real-times-complex steps, and only Re(e · q(x)) is kept.
        const cplx e = kept ? kept[i] : std::exp(piece.rate * x);
        for (int m = 0; m <= maxDerivative; ++m) {
          double re = 0.0, im = 0.0;
          for (size_t k = q[m].size(); k-- > 0;) re = re * x + q[m][k].real(), im = im * x + q[m][k].imag();
          out[static_cast<size_t>(m) * count + i] += e.real() * re - e.imag() * im;
        }
      }
    }
  }
}

}  // namespace pdesurf
