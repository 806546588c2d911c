#include "cad/face_loops.hpp"

#include <algorithm>

namespace pdesurf {

BrepPcurve usePcurve(const BSplineSurface& s, const BrepTopology& t, int f, const BrepEdgeUse& u) {
  const BrepEdge& e = t.edges[size_t(u.edge)];
  for (const BrepPcurve& p : e.pcurves)
    if (p.face == f && !(e.otherFace == f && e.face == f)) return p;
  int border = e.border;
  if (e.face == f && border == 2 && s.closedV && !u.forward) border = 3;  // the seam's v1 use
  const auto uv = [&](double x) -> Eigen::Vector2d {
    switch (border) {
      case 0: return {s.u0(), x};
      case 1: return {s.u1(), x};
      case 2: return {x, s.v0()};
      default: return {x, s.v1()};
    }
  };
  BrepPcurve p;
  p.face = f, p.degree = 1, p.knots = {e.t0, e.t0, e.t1, e.t1}, p.poles = {uv(e.t0), uv(e.t1)};
  return p;
}

std::vector<BrepEdgeUse> surfaceLoop(const BrepTopology& t, size_t f) {
  std::vector<BrepEdgeUse> uses = t.faces[f].loop;
  if (t.faces[f].flipped) {
    std::reverse(uses.begin(), uses.end());
    for (BrepEdgeUse& u : uses) u.forward = !u.forward;
  }
  return uses;
}

}  // namespace pdesurf
