#include "expr/spline.hpp"

#include <algorithm>
#include <cmath>

namespace pdesurf {

std::string SplineFn::problem(int p, const std::vector<double>& t, const std::vector<double>& c) {
  if (p < 0) return "the degree is negative";
  if (p >= kMaxBasis) return "the degree is above " + std::to_string(kMaxBasis - 1);
  if (c.size() < size_t(p) + 1) return "degree " + std::to_string(p) + " needs at least " + std::to_string(p + 1) + " coefficients";
  if (t.size() != c.size() + size_t(p) + 1)
    return std::to_string(c.size()) + " coefficients of degree " + std::to_string(p) + " need " + std::to_string(c.size() + size_t(p) + 1) +
           " knots, not " + std::to_string(t.size());
  for (size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(t[i])) return "knot " + std::to_string(i) + " is not finite";
    if (i && t[i] < t[i - 1]) return "knot " + std::to_string(i) + " is smaller than the one before";
  }
  for (size_t i = 0; i < c.size(); ++i)
    if (!std::isfinite(c[i])) return "coefficient " + std::to_string(i) + " is not finite";
  const size_t n = c.size();
  if (!(t[size_t(p)] < t[n])) return "the domain [knot p, knot n] is empty";
  for (size_t i = size_t(p) + 1; i < n;) {  // interior knots: multiplicity at most p
    size_t j = i;
    while (j < n && t[j] == t[i]) ++j;
    if (t[i] > t[size_t(p)] && t[i] < t[n] && j - i > size_t(p))
      return "the knot " + std::to_string(t[i]) + " is repeated " + std::to_string(j - i) + " times inside the domain (at most the degree, " +
             std::to_string(p) + ", keeps the function continuous)";
    i = j;
  }
  return "";
}

SplineFn::SplineFn(int degree, std::vector<double> knots, std::vector<double> coefs) : p_(degree), t_(std::move(knots)), c_(std::move(coefs)) {
  for (int i = 0; i < int(c_.size()); ++i)
    if (c_[size_t(i)] != 0.0) nonzeroLast_ = i;
  for (int i = int(c_.size()) - 1; i >= 0; --i)
    if (c_[size_t(i)] != 0.0) nonzeroFirst_ = i;
  if (p_ == 0) return;
  // d/dx Σ c_i N_{i,p} = Σ p (c_{i+1} - c_i) / (t_{i+p+1} - t_{i+1}) N_{i+1,p-1}, on the knots without their ends.
  std::vector<double> d(c_.size() - 1);
  for (size_t i = 0; i + 1 < c_.size(); ++i) {
    const double h = t_[i + size_t(p_) + 1] - t_[i + 1];
    d[i] = h > 0 ? p_ * (c_[i + 1] - c_[i]) / h : 0.0;
  }
  derivative_ = std::make_shared<const SplineFn>(p_ - 1, std::vector<double>(t_.begin() + 1, t_.end() - 1), std::move(d));
}

int SplineFn::span(double x) const {
  const int n = int(c_.size());
  if (!(x >= t_[size_t(p_)])) {  // below the domain (or NaN): the first non-empty piece
    int k = p_;
    while (k + 1 < n && t_[size_t(k) + 1] == t_[size_t(k)]) ++k;
    return k;
  }
  if (x >= t_[size_t(n)]) {  // at or past its end: the last non-empty piece
    int k = n - 1;
    while (k > p_ && t_[size_t(k)] == t_[size_t(k) + 1]) --k;
    return k;
  }
  const auto it = std::upper_bound(t_.begin() + p_, t_.begin() + n + 1, x);
  return int(it - t_.begin()) - 1;
}

void SplineFn::basis(int k, double x, double* N) const {
  // The triangular recursion for the non-zero B-splines on piece k (Piegl & Tiller, A2.2):
  // every denominator spans [t_k, t_{k+1}], a non-empty piece; inside it, sums of positive terms.
  double left[kMaxBasis], right[kMaxBasis];
  N[0] = 1.0;
  for (int j = 1; j <= p_; ++j) {
    left[j] = x - t_[size_t(k + 1 - j)];
    right[j] = t_[size_t(k + j)] - x;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      const double temp = N[r] / (right[r + 1] + left[j - r]);
      N[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    N[j] = saved;
  }
}

double SplineFn::combine(int k, const double* N) const {
  if (k - p_ > nonzeroLast_ || k < nonzeroFirst_) return 0.0;
  const double* c = c_.data() + (k - p_);
  double sum = 0.0;
  for (int j = 0; j <= p_; ++j) sum += c[j] * N[j];
  return sum;
}

double SplineFn::eval(double x) const {
  if (std::isnan(x)) return x;
  const int k = span(x);
  double N[kMaxBasis];
  basis(k, x, N);
  return combine(k, N);
}

double SplineFn::derivativeAt(double x, int k) const {
  const SplineFn* f = this;
  for (int i = 0; i < k; ++i) {
    if (!f->derivative_) return std::isnan(x) ? x : 0.0;
    f = f->derivative_.get();
  }
  return f->eval(x);
}

bool SplineFn::range(double a, double b, double* lo, double* hi) const {
  if (!(a <= b) || !std::isfinite(a) || !std::isfinite(b)) return false;
  // Inside the domain: the hull of the coefficients of the pieces [a, b] spans.
  const double ia = std::max(a, this->lo()), ib = std::min(b, this->hi());
  bool any = false;
  if (ia <= ib) {
    const int k0 = span(ia), k1 = span(ib);
    const auto first = c_.begin() + (k0 - p_), last = c_.begin() + k1 + 1;
    *lo = *std::min_element(first, last), *hi = *std::max_element(first, last);
    any = true;
  }
  // Past an end (an argument's enclosure widened by rounding, or a curve leaving the domain):
  // the end piece continues as its Taylor polynomial, |f(x) - f(e)| <= Σ_k |f^(k)(e)|/k! δ^k.
  for (const auto& [e, d] : {std::pair<double, double>{this->lo(), this->lo() - a}, {this->hi(), b - this->hi()}}) {
    if (!(d > 0)) continue;
    const double f = eval(e);
    double spread = 0.0, power = 1.0, factorial = 1.0;
    for (int k = 1; k <= p_; ++k) {
      power *= d, factorial *= k;
      spread += std::abs(derivativeAt(e, k)) / factorial * power;
    }
    // The rounding of f(e), of the derivatives and of the sum (de Boor's convex combinations
    // round within a few ulps of the largest coefficient).
    double largest = 0.0;
    for (double c : c_) largest = std::max(largest, std::abs(c));
    spread = spread * (1.0 + 1e-12) + 1e-13 * largest;
    if (!std::isfinite(spread)) return false;
    *lo = any ? std::min(*lo, f - spread) : f - spread;
    *hi = any ? std::max(*hi, f + spread) : f + spread;
    any = true;
  }
  return any;
}

std::vector<double> SplineFn::breaks() const {
  std::vector<double> out;
  for (size_t i = size_t(p_) + 1; i < c_.size(); ++i)
    if (t_[i] > lo() && t_[i] < hi() && (out.empty() || out.back() != t_[i])) out.push_back(t_[i]);
  return out;
}

std::vector<double> SplineFn::kinks() const {
  std::vector<double> out;
  for (size_t i = size_t(p_) + 1; i < c_.size(); ++i)
    if (p_ > 0 && t_[i] > lo() && t_[i] < hi() && t_[i + size_t(p_) - 1] == t_[i] && t_[i - 1] != t_[i]) out.push_back(t_[i]);
  return out;
}

}  // namespace pdesurf
