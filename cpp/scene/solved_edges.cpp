#include "scene/solved_edges.hpp"

#include <cmath>

#include "basis/general_function.hpp"
#include "common/errors.hpp"

namespace pdesurf {

namespace {

Expr v() { return variable(ExprVar::V); }

Expr scaled(double c, const Expr& e) { return c == 1.0 ? e : multiply(constant(c), e); }

Expr sum(const Expr& a, const Expr& b) { return a ? add(a, b) : b; }

// Σ_j c_j B_j^m(v) written in powers of v (degree m is small: a Bézier net's).
Expr bernsteinPolynomial(const std::vector<double>& c) {
  const int m = static_cast<int>(c.size()) - 1;
  std::vector<double> binom(m + 1, 1.0);
  for (int j = 1; j <= m; ++j) binom[j] = binom[j - 1] * (m - j + 1) / j;
  Expr out = constant(0.0);
  for (int k = 0; k <= m; ++k) {
    // r^k's coefficient: Σ_{j<=k} c_j C(m, j) C(m - j, k - j) (-1)^(k - j).
    double a = 0.0;
    for (int j = 0; j <= k; ++j) {
      double inner = 1.0;  // C(m - j, k - j)
      for (int q = 1; q <= k - j; ++q) inner = inner * (m - j - q + 1) / q;
      a += c[j] * binom[j] * inner * ((k - j) % 2 ? -1.0 : 1.0);
    }
    if (a != 0.0) out = add(out, scaled(a, k == 0 ? constant(1.0) : power(v(), constant(k))));
  }
  return out;
}

// A Bézier border from the solved net: row (or column) `at` and its two neighbours inward.
EdgeExprs bezierEdge(const SolvedPatch& sp, int edge, int derivatives) {
  const BezierProblem& b = sp.patch->bezier();
  const std::vector<Eigen::Vector3d>& net = sp.controlNet;
  const bool alongV = edge < 2;               // u0, u1 run along v (index j)
  const int across = alongV ? b.n : b.m;      // the degree across the border
  const int along = alongV ? b.m : b.n;
  const bool far = edge % 2 == 1;
  auto P = [&](int ring, int k) -> const Eigen::Vector3d& {
    const int i = far ? across - ring : ring;
    return alongV ? net[b.index(i, k)] : net[b.index(k, i)];
  };
  EdgeExprs e;
  for (int c = 0; c < 3; ++c) {
    std::vector<double> x(along + 1), d(along + 1), dd(along + 1);
    for (int k = 0; k <= along; ++k) {
      x[k] = P(0, k)[c];
      // Out of the patch: at the near border towards lower index, i.e. -d/du.
      d[k] = across >= 1 ? -across * (P(1, k)[c] - P(0, k)[c]) : 0.0;
      dd[k] = across >= 2 ? across * (across - 1) * (P(2, k)[c] - 2 * P(1, k)[c] + P(0, k)[c]) : 0.0;
    }
    e.X[c] = bernsteinPolynomial(x);
    e.out[c] = bernsteinPolynomial(d);
    e.outOut[c] = derivatives >= 2 ? bernsteinPolynomial(dd) : constant(0.0);
  }
  e.a0 = 0.0, e.a1 = 1.0;
  return e;
}

// The boundary slot ∂^d X_c/∂u^d of the problem a pde patch was solved for, at its edge u0 or
// u1, when its method imposes the data exactly (the lift: modal, closed, reference); else null.
const VExpansion* dataAt(const SolvedPatch& sp, int edge, int c, int d) {
  if (!sp.patch->solvedAsPde() || sp.surface.pointwise[c]) return nullptr;
  const MethodKind kind = sp.used.kind;
  if (kind != MethodKind::Modal && kind != MethodKind::Closed && kind != MethodKind::Reference) return nullptr;
  const ComponentProblem& cp = sp.pde().component[c];
  const std::vector<VExpansion>& side = edge == 1 ? cp.right : cp.left;
  return d < static_cast<int>(side.size()) ? &side[d] : nullptr;
}

}  // namespace

Expr functionExpr(const VFunction& g) {
  switch (g.family) {
    case Family::Poly: {
      if (g.n == 0) return constant(1.0);
      const Expr base = multiply(subtract(v(), constant(g.c)), constant(g.w));
      return g.n == 1 ? base : power(base, constant(g.n));
    }
    case Family::Cos: return call(ExprFn::Cos, scaled(g.w, v()));
    case Family::Sin: return call(ExprFn::Sin, scaled(g.w, v()));
    case Family::Exp: return call(ExprFn::Exp, scaled(g.w, v()));
    case Family::Cosh: return call(ExprFn::Cosh, scaled(g.w, v()));
    case Family::Sinh: return call(ExprFn::Sinh, scaled(g.w, v()));
    case Family::General: return g.general->expr();
    case Family::Bernstein: break;
  }
  throw Error(ErrorCode::Internal, "a Bernstein function outside a Bézier patch");
}

EdgeExprs solvedEdge(const SolvedPatch& sp, int edge, int derivatives) {
  if (sp.patch->kind == PatchKind::Bezier) return bezierEdge(sp, edge, derivatives);
  const SeparableSurface& s = sp.surface;
  const double u = edge == 1 ? s.u1 : s.u0;
  const double sign = edge == 1 ? 1.0 : -1.0;  // out of the patch: +u at u1, -u at u0
  EdgeExprs e;
  e.a0 = s.v0, e.a1 = s.v1;
  for (int c = 0; c < 3; ++c) {
    std::array<Expr, 3> k;  // the u-derivatives 0, 1, 2 along the edge
    for (int d = 0; d <= derivatives; ++d) {
      // Where the method imposed the patch's own data exactly, the edge is those data as given:
      // not the solve's evaluation, whose rounding (the far end's modes cancelled by the lift)
      // would make the edge, and whatever is built on it, depend on the far end's patch.
      if (const VExpansion* slot = dataAt(sp, edge, c, d)) {
        for (const VTerm& t : *slot) k[d] = sum(k[d], scaled(t.coef, functionExpr(t.g)));
        continue;
      }
      for (const SeparableTerm& t : s.component[c]) {
        const double coef = t.G.eval(u, d);
        if (coef != 0.0) k[d] = sum(k[d], scaled(coef, functionExpr(t.g)));
      }
    }
    if (s.pointwise[c]) {
      Expr p = s.pointwise[c];
      for (int d = 0; d <= derivatives; ++d) {
        k[d] = sum(k[d], substitute(p, ExprVar::U, constant(u)));
        if (d < derivatives) p = derivative(p, ExprVar::U);
      }
    }
    for (Expr& x : k)
      if (!x) x = constant(0.0);
    e.X[c] = k[0];
    e.out[c] = derivatives >= 1 ? scaled(sign, k[1]) : constant(0.0);
    e.outOut[c] = derivatives >= 2 ? k[2] : constant(0.0);
  }
  return e;
}

}  // namespace pdesurf
