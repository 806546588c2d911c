#include "cad/bspline_curve.hpp"

#include <algorithm>

namespace pdesurf {

namespace {

int multiplicity(const std::vector<double>& knots, double t) { return int(std::count(knots.begin(), knots.end(), t)); }

// One knot t inserted (The NURBS Book A5.1 with r = 1): the curve is unchanged.
void insertKnot(BSplineCurve& c, double t) {
  const int p = c.degree, n = int(c.poles.size());
  const int k = findSpan(c.knots, p, n, t);
  std::vector<Eigen::Vector3d> q(size_t(n) + 1);
  for (int i = 0; i <= k - p; ++i) q[size_t(i)] = c.poles[size_t(i)];
  for (int i = k - p + 1; i <= k; ++i) {
    const double alpha = (t - c.knots[size_t(i)]) / (c.knots[size_t(i + p)] - c.knots[size_t(i)]);
    q[size_t(i)] = alpha * c.poles[size_t(i)] + (1 - alpha) * c.poles[size_t(i - 1)];
  }
  for (int i = k + 1; i <= n; ++i) q[size_t(i)] = c.poles[size_t(i - 1)];
  c.knots.insert(c.knots.begin() + k + 1, t);
  c.poles = std::move(q);
}

}  // namespace

BSplineCurve borderCurve(const BSplineSurface& s, int border) {
  BSplineCurve c;
  const bool alongV = border < 2;
  c.degree = alongV ? s.degreeV : s.degreeU;
  c.knots = alongV ? s.knotsV : s.knotsU;
  const int fixed = alongV ? (border == 0 ? 0 : s.countU - 1) : (border == 2 ? 0 : s.countV - 1);
  const int count = alongV ? s.countV : s.countU;
  for (int k = 0; k < count; ++k) c.poles.push_back(alongV ? s.pole(fixed, k) : s.pole(k, fixed));
  return c;
}

BSplineCurve subCurve(const BSplineCurve& curve, double a, double b) {
  BSplineCurve c = curve;
  const int p = c.degree;
  for (double t : {a, b})
    if (t > c.knots.front() && t < c.knots.back())
      while (multiplicity(c.knots, t) < p) insertKnot(c, t);
  const int size = int(c.knots.size());
  int s = int(std::find(c.knots.begin(), c.knots.end(), a) - c.knots.begin());
  int e = int(std::find(c.knots.rbegin(), c.knots.rend(), b).base() - c.knots.begin()) - 1;
  s = std::max(s, 1), e = std::min(e, size - 2);
  BSplineCurve out;
  out.degree = p;
  out.knots.push_back(a);
  out.knots.insert(out.knots.end(), c.knots.begin() + s, c.knots.begin() + e + 1);
  out.knots.push_back(b);
  out.poles.assign(c.poles.begin() + (s - 1), c.poles.begin() + (e - p) + 1);
  return out;
}

Eigen::Vector3d evaluate(const BSplineCurve& c, double t) {
  const int p = c.degree, n = int(c.poles.size());
  const int span = findSpan(c.knots, p, n, t);
  std::vector<double> N(size_t(p + 1));
  basisDerivatives(c.knots, p, span, t, 0, N.data());
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int r = 0; r <= p; ++r) x += N[size_t(r)] * c.poles[size_t(span - p + r)];
  return x;
}

}  // namespace pdesurf
