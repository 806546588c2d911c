#include "cad/bspline_surface.hpp"

#include <algorithm>
#include <cmath>

namespace pdesurf {

int findSpan(const std::vector<double>& knots, int degree, int count, double t) {
  if (t >= knots[count]) return count - 1;
  if (t <= knots[degree]) return degree;
  // First knot > t, minus one: the span [knots[i], knots[i+1]) holding t.
  auto it = std::upper_bound(knots.begin() + degree, knots.begin() + count + 1, t);
  return int(it - knots.begin()) - 1;
}

void basisDerivatives(const std::vector<double>& knots, int p, int span, double t, int n, double* ders) {
  // The NURBS Book A2.3 with fixed small arrays (degree <= kMaxBSplineDegree).
  constexpr int N = kMaxBSplineDegree + 1;
  double ndu[N][N], a[2][N], left[N], right[N];
  ndu[0][0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = t - knots[span + 1 - j];
    right[j] = knots[span + j] - t;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];
      const double temp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }
  for (int r = 0; r <= p; ++r) ders[r] = ndu[r][p];
  for (int k = 1; k <= n; ++k)
    for (int r = 0; r <= p; ++r) ders[k * (p + 1) + r] = 0.0;
  for (int r = 0; r <= p; ++r) {
    int s1 = 0, s2 = 1;
    a[0][0] = 1.0;
    for (int k = 1; k <= n && k <= p; ++k) {
      double d = 0.0;
      const int rk = r - k, pk = p - k;
      if (r >= k) {
        a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
        d = a[s2][0] * ndu[rk][pk];
      }
      const int j1 = rk >= -1 ? 1 : -rk;
      const int j2 = (r - 1 <= pk) ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j) {
        a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
        d += a[s2][j] * ndu[rk + j][pk];
      }
      if (r <= pk) {
        a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
        d += a[s2][k] * ndu[r][pk];
      }
      ders[k * (p + 1) + r] = d;
      std::swap(s1, s2);
    }
  }
  double f = p;
  for (int k = 1; k <= n; ++k) {
    for (int r = 0; r <= p; ++r) ders[k * (p + 1) + r] *= f;
    f *= (p - k);
  }
}

Eigen::Vector3d evaluate(const BSplineSurface& s, double u, double v, int du, int dv) {
  const int p = s.degreeU, q = s.degreeV;
  if (du > p || dv > q) return Eigen::Vector3d::Zero();
  double nu[(kMaxBSplineDegree + 1) * (kMaxBSplineDegree + 1)], nv[(kMaxBSplineDegree + 1) * (kMaxBSplineDegree + 1)];
  const int su = findSpan(s.knotsU, p, s.countU, u), sv = findSpan(s.knotsV, q, s.countV, v);
  basisDerivatives(s.knotsU, p, su, u, du, nu);
  basisDerivatives(s.knotsV, q, sv, v, dv, nv);
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  for (int a = 0; a <= p; ++a) {
    Eigen::Vector3d row = Eigen::Vector3d::Zero();
    for (int b = 0; b <= q; ++b) row += nv[dv * (q + 1) + b] * s.pole(su - p + a, sv - q + b);
    out += nu[du * (p + 1) + a] * row;
  }
  return out;
}

bool wellFormed(const BSplineSurface& s, std::string* why) {
  auto fail = [&](const char* m) {
    if (why) *why = m;
    return false;
  };
  if (s.degreeU < 1 || s.degreeU > kMaxBSplineDegree || s.degreeV < 1 || s.degreeV > kMaxBSplineDegree) return fail("degree outside 1..16");
  if (s.countU <= s.degreeU || s.countV <= s.degreeV) return fail("fewer poles than degree + 1");
  if (s.knotsU.size() != size_t(s.countU + s.degreeU + 1) || s.knotsV.size() != size_t(s.countV + s.degreeV + 1))
    return fail("knot vector sizes do not match the pole counts");
  if (s.poles.size() != size_t(s.countU) * s.countV) return fail("pole count");
  for (const auto* k : {&s.knotsU, &s.knotsV}) {
    for (size_t i = 1; i < k->size(); ++i)
      if (!((*k)[i] >= (*k)[i - 1])) return fail("knots decrease or are not finite");
  }
  for (int e = 0; e < s.degreeU; ++e)
    if (s.knotsU[e] != s.knotsU[e + 1] || s.knotsU[s.knotsU.size() - 1 - e] != s.knotsU[s.knotsU.size() - 2 - e])
      return fail("u knots not clamped");
  for (int e = 0; e < s.degreeV; ++e)
    if (s.knotsV[e] != s.knotsV[e + 1] || s.knotsV[s.knotsV.size() - 1 - e] != s.knotsV[s.knotsV.size() - 2 - e])
      return fail("v knots not clamped");
  for (const auto& p : s.poles)
    if (!p.allFinite()) return fail("a pole is not finite");
  return true;
}

}  // namespace pdesurf
