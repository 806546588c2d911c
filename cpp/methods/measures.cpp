#include "methods/measures.hpp"

#include <algorithm>
#include <cmath>

#include "basis/general_function.hpp"
#include "expr/taylor.hpp"
#include "methods/approximate.hpp"
#include "surface/mesh.hpp"

namespace pdesurf {

double relativeError(const SeparableSurface& ref, const SeparableSurface& other, int Iu, int Jv) {
  // The sample grid of tessellation is exactly u_i = i/(Iu-1), v_j = v0 + (v1-v0) j/(Jv-1).
  const GridSamples a = sampleGrid(ref, Iu - 1, Jv - 1), b = sampleGrid(other, Iu - 1, Jv - 1);
  double sum = 0.0;
  for (size_t k = 0; k < a.X.size(); k += 3) {
    const Eigen::Vector3d pa(a.X[k], a.X[k + 1], a.X[k + 2]), pb(b.X[k], b.X[k + 1], b.X[k + 2]);
    sum += (pa - pb).norm() / pa.norm();
  }
  return sum / (static_cast<double>(Iu) * Jv);
}

double boundaryConditionError(const PdeProblem& p, const SeparableSurface& s, int samples) {
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) {
    const ComponentProblem& cp = p.component[c];
    for (int end = 0; end < 2; ++end)
      for (size_t i = 0; i < cp.left.size(); ++i)
        for (int k = 0; k <= samples; ++k) {
          const double v = p.v0 + (p.v1 - p.v0) * k / samples;
          const double want = expansionValue((end == 0 ? cp.left : cp.right)[i], v);
          const double got = evalComponent(s, c, end, v, static_cast<int>(i), 0);
          worst = std::max(worst, std::abs(got - want) / std::max(1.0, std::abs(want)));
        }
  }
  return worst;
}

namespace {

// The force f of component c at (u, v): products of a u-polynomial and a v-function, and
// expressions in u and v.
double forceAt(const ComponentProblem& cp, double u, double v) {
  double f = 0.0;
  for (const ForceTerm& t : cp.force) {
    double q = 0.0;
    for (size_t k = t.uPoly.size(); k-- > 0;) q = q * u + t.uPoly[k];
    f += q * t.g.eval(v);
  }
  const double vars[2] = {v, u};
  for (const GeneralForce& g : cp.generalForce) f += evaluate(*g.f, vars);
  return f;
}

// L X - f of component c at (u, v); *size gets Σ_k |α_k ∂ X| + |f|.
double residualAt(const ComponentProblem& cp, const SeparableSurface& s, int c, double u, double v, double* size) {
  const int n = static_cast<int>(cp.alpha.size()) - 1;
  const double f = forceAt(cp, u, v);
  double sum = -f, mag = std::abs(f);
  for (int k = 0; k <= n; ++k) {
    const double part = cp.alpha[k] * evalComponent(s, c, u, v, 2 * (n - k), 2 * k);
    sum += part;
    mag += std::abs(part);
  }
  *size = mag;
  return sum;
}

}  // namespace

double pdeResidual(const PdeProblem& p, const SeparableSurface& s) {
  double worst = 0.0;
  for (int c = 0; c < 3; ++c)
    for (int iu = 1; iu < 20; ++iu)
      for (int iv = 0; iv <= 20; ++iv) {
        double mag = 0.0;
        const double r = residualAt(p.component[c], s, c, iu / 20.0, p.v0 + (p.v1 - p.v0) * iv / 20, &mag);
        worst = std::max(worst, std::abs(r) / std::max(1.0, mag));
      }
  return worst;
}

// The residual on the grid's interior points as separable sums tabulated once per grid line:
// each term's u-factor and its derivatives up to 2n at every u_i, its v-factor's at every v_j
// (a general one's from one Taylor expansion per v_j, all orders at once), then per point
// Σ_k α_k Σ_t G_t^(2(n-k))(u_i) g_t^(2k)(v_j). Point by point, a heavy fill's general
// functions were re-expanded for every point and order: 11 s for one check (issue 38 #2).
PdeResidual interiorResidual(const PdeProblem& p, const SeparableSurface& s, int grid) {
  const int m = grid - 1;  // interior points per direction
  PdeResidual out;
  if (m < 1) return out;
  std::vector<double> us(static_cast<size_t>(m)), vs(static_cast<size_t>(m));
  for (int i = 1; i < grid; ++i) us[size_t(i - 1)] = static_cast<double>(i) / grid;
  for (int j = 1; j < grid; ++j) vs[size_t(j - 1)] = p.v0 + (p.v1 - p.v0) * j / grid;
  const size_t points = static_cast<size_t>(m) * m;
  std::vector<double> worst(points, 0.0);  // the largest |residual| of the three components
  double scale = 0.0;
  ExpOnGrid exps(us.data(), m);
  for (int c = 0; c < 3; ++c) {
    const ComponentProblem& cp = p.component[c];
    const int n = static_cast<int>(cp.alpha.size()) - 1, D = 2 * n;
    // parts[k][q]: Σ_t G_t^(2(n-k))(u_i) g_t^(2k)(v_j) at point q = j·m + i.
    std::vector<std::vector<double>> parts(static_cast<size_t>(n + 1), std::vector<double>(points, 0.0));
    std::vector<double> uTab(static_cast<size_t>(D + 1) * m), vTab(static_cast<size_t>(D + 1) * m), up(static_cast<size_t>(D + 1));
    for (const SeparableTerm& t : s.component[c]) {
      t.G.tabulate(us.data(), m, D, uTab.data(), nullptr, &exps);
      for (int j = 0; j < m; ++j) {
        if (t.g.family == Family::General) {
          const double vars[2] = {vs[size_t(j)], 0.0};
          const std::vector<double> coef = taylorCoefficients(*t.g.general->expr(), ExprVar::V, vars, D);
          double factorial = 1.0;
          for (int b = 0; b <= D; ++b) up[size_t(b)] = coef[size_t(b)] * (factorial *= (b > 0 ? b : 1));
        } else {
          t.g.evalUpTo(vs[size_t(j)], D, up.data());
        }
        for (int b = 0; b <= D; ++b) vTab[size_t(b) * m + size_t(j)] = up[size_t(b)];
      }
      for (int k = 0; k <= n; ++k) {
        const double* Gu = uTab.data() + static_cast<size_t>(2 * (n - k)) * m;
        const double* gv = vTab.data() + static_cast<size_t>(2 * k) * m;
        std::vector<double>& part = parts[size_t(k)];
        for (int j = 0; j < m; ++j)
          for (int i = 0; i < m; ++i) part[size_t(j) * m + size_t(i)] += Gu[i] * gv[j];
      }
    }
    std::vector<double> sum(points, 0.0), mag(points, 0.0);
    for (int k = 0; k <= n; ++k)
      for (size_t q = 0; q < points; ++q) {
        const double term = cp.alpha[k] * parts[size_t(k)][q];
        sum[q] += term, mag[q] += std::abs(term);
      }
    // The force, point by point.
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        const double f = forceAt(cp, us[size_t(i)], vs[size_t(j)]);
        const size_t q = size_t(j) * m + size_t(i);
        const double r = std::abs(sum[q] - f), size = mag[q] + std::abs(f);
        worst[q] = std::isfinite(size) && std::isfinite(r) && !std::isnan(worst[q]) ? std::max(worst[q], r) : NAN;
        scale = std::max(scale, size);
      }
  }
  double worstAbs = -1.0;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const double r = worst[size_t(j) * m + size_t(i)];
      if (!(r <= worstAbs)) worstAbs = r, out.u = us[size_t(i)], out.v = vs[size_t(j)];  // NaN wins
      if (std::isnan(r)) return out.absolute = out.relative = NAN, out;
    }
  out.absolute = worstAbs;
  out.relative = worstAbs / std::max(scale, 1e-300);
  return out;
}

}  // namespace pdesurf
