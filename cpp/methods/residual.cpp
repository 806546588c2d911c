#include "methods/residual.hpp"

#include <algorithm>
#include <cmath>

#include "methods/approximate.hpp"

namespace pdesurf {

namespace {

double force(const ComponentProblem& cp, double u, double v) {
  double f = 0.0;
  for (const ForceTerm& t : cp.force) {
    double poly = 0.0;
    for (size_t k = t.uPoly.size(); k-- > 0;) poly = poly * u + t.uPoly[k];
    f += poly * t.g.eval(v);
  }
  const double vars[2] = {v, u};
  for (const GeneralForce& g : cp.generalForce) f += evaluate(*g.f, vars);
  return f;
}

}  // namespace

PdeResidual pdeResidual(const SeparableSurface& s, const PdeProblem& p, int grid) {
  PdeResidual out;
  double scale = 0.0;
  std::vector<double> abs, size, us, vs;
  for (int i = 1; i < grid; ++i)
    for (int j = 1; j < grid; ++j) {
      const double u = static_cast<double>(i) / grid, v = p.v0 + (p.v1 - p.v0) * j / grid;
      double worst = 0.0, worstSize = 0.0;
      for (int c = 0; c < 3; ++c) {
        const ComponentProblem& cp = p.component[c];
        const int n = static_cast<int>(cp.alpha.size()) - 1;
        double lx = 0.0, terms = 0.0;
        for (int k = 0; k <= n; ++k) {
          const double t = cp.alpha[k] * evalComponent(s, c, u, v, 2 * (n - k), 2 * k);
          lx += t;
          terms += std::abs(t);
        }
        const double r = std::abs(lx - force(cp, u, v));
        if (!(r <= worst)) worst = r;  // NaN propagates
        worstSize = std::max(worstSize, terms);
      }
      abs.push_back(worst), size.push_back(worstSize), us.push_back(u), vs.push_back(v);
      scale = std::max(scale, worstSize);
      if (!(worst <= out.absolute)) out.absolute = worst;
    }
  double worstRel = -1.0;
  for (size_t k = 0; k < abs.size(); ++k) {
    const double rel = abs[k] / std::max(scale, 1e-300);
    if (!(rel <= worstRel)) worstRel = rel, out.u = us[k], out.v = vs[k];
  }
  out.relative = worstRel;
  return out;
}

}  // namespace pdesurf
