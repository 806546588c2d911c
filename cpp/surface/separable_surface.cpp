#include "surface/separable_surface.hpp"

namespace pdesurf {

double evalComponent(const SeparableSurface& s, int c, double u, double v, int du, int dv) {
  double sum = 0.0;
  for (const SeparableTerm& t : s.component[c]) sum += t.G.eval(u, du) * t.g.eval(v, dv);
  return sum;
}

Eigen::Vector3d evalPoint(const SeparableSurface& s, double u, double v, int du, int dv) {
  return {evalComponent(s, 0, u, v, du, dv), evalComponent(s, 1, u, v, du, dv), evalComponent(s, 2, u, v, du, dv)};
}

}  // namespace pdesurf
