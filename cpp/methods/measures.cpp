#include "methods/measures.hpp"

#include <algorithm>
#include <cmath>

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

// L X - f of component c at (u, v); *size gets Σ_k |α_k ∂ X| + |f|.
double residualAt(const ComponentProblem& cp, const SeparableSurface& s, int c, double u, double v, double* size) {
  const int n = static_cast<int>(cp.alpha.size()) - 1;
  double f = 0.0;
  for (const ForceTerm& t : cp.force) {
    double q = 0.0;
    for (size_t k = t.uPoly.size(); k-- > 0;) q = q * u + t.uPoly[k];
    f += q * t.g.eval(v);
  }
  const double vars[2] = {v, u};
  for (const GeneralForce& g : cp.generalForce) f += evaluate(*g.f, vars);
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

PdeResidual interiorResidual(const PdeProblem& p, const SeparableSurface& s, int grid) {
  PdeResidual out;
  double scale = 0.0, worstAbs = -1.0;
  for (int i = 1; i < grid; ++i)
    for (int j = 1; j < grid; ++j) {
      const double u = static_cast<double>(i) / grid, v = p.v0 + (p.v1 - p.v0) * j / grid;
      double r = 0.0;
      for (int c = 0; c < 3; ++c) {
        double mag = 0.0;
        r = std::max(r, std::abs(residualAt(p.component[c], s, c, u, v, &mag)));
        if (!std::isfinite(mag) || !std::isfinite(r)) r = NAN;
        scale = std::max(scale, mag);
      }
      if (!(r <= worstAbs)) worstAbs = r, out.u = u, out.v = v;  // NaN wins
    }
  out.absolute = worstAbs;
  out.relative = worstAbs / std::max(scale, 1e-300);
  return out;
}

}  // namespace pdesurf
