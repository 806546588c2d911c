#include "surface/same_surface.hpp"

#include "basis/general_function.hpp"

namespace pdesurf {

bool sameFunction(const VFunction& a, const VFunction& b) {
  if (a.isGeneral() != b.isGeneral()) return false;
  // Expressions are interned: the same expression is the same node while either is alive.
  if (a.isGeneral()) return a.general->expr() == b.general->expr();
  return a == b;
}

namespace {

bool sameFactor(const UFactor& a, const UFactor& b) {
  if (a.bernstein != b.bernstein || a.pieces.size() != b.pieces.size()) return false;
  for (size_t i = 0; i < a.pieces.size(); ++i) {
    const ExpPoly &x = a.pieces[i], &y = b.pieces[i];
    if (x.rate != y.rate || x.shift != y.shift || x.poly != y.poly) return false;
  }
  return true;
}

}  // namespace

bool sameSurface(const SeparableSurface& a, const SeparableSurface& b) {
  if (a.u0 != b.u0 || a.u1 != b.u1 || a.v0 != b.v0 || a.v1 != b.v1) return false;
  for (int c = 0; c < 3; ++c) {
    const auto &x = a.component[size_t(c)], &y = b.component[size_t(c)];
    if (x.size() != y.size() || a.pointwise[size_t(c)] != b.pointwise[size_t(c)] ||
        a.pointwisePartials[size_t(c)] != b.pointwisePartials[size_t(c)])
      return false;
    for (size_t t = 0; t < x.size(); ++t)
      if (!sameFunction(x[t].g, y[t].g) || !sameFactor(x[t].G, y[t].G)) return false;
  }
  return true;
}

}  // namespace pdesurf
