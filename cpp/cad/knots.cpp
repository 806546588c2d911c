#include "cad/knots.hpp"

#include "cad/bspline_surface.hpp"

namespace pdesurf {

std::vector<double> clampedKnots(const std::vector<double>& breaks, int p, const std::vector<bool>* creases) {
  std::vector<double> k(size_t(p), breaks.front());
  for (size_t i = 0; i < breaks.size(); ++i) {
    const bool inner = i > 0 && i + 1 < breaks.size();
    const int times = inner && creases && (*creases)[i] ? p : 1;
    k.insert(k.end(), size_t(times), breaks[i]);
  }
  k.insert(k.end(), size_t(p), breaks.back());
  return k;
}

std::vector<double> periodicKnots(const std::vector<double>& breaks, int p) {
  const int n = int(breaks.size()) - 1;
  const double period = breaks.back() - breaks.front();
  std::vector<double> k;
  for (int i = -p; i <= n + p; ++i) {
    const int wrapped = ((i % n) + n) % n;
    const int turns = (i - wrapped) / n;
    k.push_back(breaks[size_t(wrapped)] + turns * period);
  }
  return k;
}

Eigen::SparseMatrix<double> collocation(const std::vector<double>& knots, int p, const std::vector<double>& t, int d, int fold) {
  const int count = int(knots.size()) - p - 1;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(t.size() * size_t(p + 1));
  double ders[(kMaxBSplineDegree + 1) * (kMaxBSplineDegree + 1)];
  for (size_t i = 0; i < t.size(); ++i) {
    const int span = findSpan(knots, p, count, t[i]);
    basisDerivatives(knots, p, span, t[i], d, ders);
    for (int r = 0; r <= p; ++r) {
      int j = span - p + r;
      if (fold > 0) j %= fold;
      entries.emplace_back(int(i), j, d <= p ? ders[d * (p + 1) + r] : 0.0);
    }
  }
  Eigen::SparseMatrix<double> out(Eigen::Index(t.size()), fold > 0 ? fold : count);
  out.setFromTriplets(entries.begin(), entries.end());  // sums the folded duplicates
  return out;
}

void insertKnot(std::vector<double>& knots, Eigen::MatrixXd& poles, int p, double t) {
  const int count = int(poles.rows());
  const int k = findSpan(knots, p, count, t);
  Eigen::MatrixXd out(count + 1, poles.cols());
  for (int i = 0; i <= k - p; ++i) out.row(i) = poles.row(i);
  for (int i = k + 1; i <= count; ++i) out.row(i) = poles.row(i - 1);
  for (int i = k - p + 1; i <= k; ++i) {
    const double a = (t - knots[size_t(i)]) / (knots[size_t(i + p)] - knots[size_t(i)]);
    out.row(i) = a * poles.row(i) + (1 - a) * poles.row(i - 1);
  }
  knots.insert(knots.begin() + k + 1, t);
  poles.swap(out);
}

void periodicToClamped(const std::vector<double>& breaks, int p, const Eigen::MatrixXd& periodic,
                       std::vector<double>* knotsOut, Eigen::MatrixXd* polesOut) {
  const int n = int(breaks.size()) - 1;
  std::vector<double> knots = periodicKnots(breaks, p);
  Eigen::MatrixXd poles(n + p, periodic.cols());
  for (int i = 0; i < n + p; ++i) poles.row(i) = periodic.row(i % n);
  // Raise b_0 and b_n to multiplicity p + 1 (each appears once): the curve on [b_0, b_n] then
  // stands alone between them, clamped.
  for (int r = 0; r < p; ++r) insertKnot(knots, poles, p, breaks.front());
  for (int r = 0; r < p; ++r) insertKnot(knots, poles, p, breaks.back());
  // Knots: p leading (wrapped) knots below b_0, then b_0 × (p+1), …; the clamped curve's
  // first pole is the one whose support starts at the first b_0.
  const int first = p;  // index of the first b_0 in the new vector
  const int count = n + p;
  knotsOut->assign(knots.begin() + first, knots.begin() + first + count + p + 1);
  *polesOut = poles.middleRows(first, count);
  // The two ends are the same point up to rounding: make them identical (a closed seam).
  polesOut->row(count - 1) = polesOut->row(0);
}

}  // namespace pdesurf
