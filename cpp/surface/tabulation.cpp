#include "surface/tabulation.hpp"

#include <cmath>
#include <string>
#include <unordered_map>
#include <utility>

#include "common/text.hpp"
#include "basis/general_function.hpp"
#include "bezier/bernstein.hpp"
#include "common/errors.hpp"

namespace pdesurf {

void checkGrid(int nu, int nv) {
  if (nu < 1 || nv < 1 || nu > kMaxGrid || nv > kMaxGrid)
    throw Error(ErrorCode::GridSize, "grid " + std::to_string(nu) + "x" + std::to_string(nv) +
                                         " is outside 1x1 .. " + std::to_string(kMaxGrid) + "x" + std::to_string(kMaxGrid));
}

Tabulation tabulate(const SeparableSurface& s, int nu, int nv, int maxDerivative) {
  checkGrid(nu, nv);
  std::vector<double> u(nu + 1), v(nv + 1);
  // Both ends exactly, so boundary rows reproduce the boundary conditions.
  for (int i = 0; i <= nu; ++i) u[i] = i == nu ? s.u1 : s.u0 + (s.u1 - s.u0) * i / nu;
  for (int j = 0; j <= nv; ++j) v[j] = j == nv ? s.v1 : s.v0 + (s.v1 - s.v0) * j / nv;
  return tabulateAt(s, std::move(u), std::move(v), maxDerivative);
}

Tabulation tabulateAt(const SeparableSurface& s, std::vector<double> us, std::vector<double> vs, int maxDerivative) {
  // A single line (one u or one v) is a grid too: an edge's samples tabulate only their edge.
  if (us.empty() || vs.empty() || us.size() > size_t(kMaxGrid) + 1 || vs.size() > size_t(kMaxGrid) + 1)
    checkGrid(int(us.size()) - 1, int(vs.size()) - 1);
  // The rows always combine the first partials (combine_rows.hpp): order 0 would read past them.
  if (maxDerivative < 1 || maxDerivative > 2) throw Error(ErrorCode::Internal, "tabulateAt: maxDerivative " + std::to_string(maxDerivative) + " (1 or 2)");
  Tabulation t;
  const int D = maxDerivative + 1;
  t.depth = D;
  const int nu = int(us.size()) - 1, nv = int(vs.size()) - 1;
  t.nu = nu;
  t.nv = nv;
  t.u = std::move(us);
  t.v = std::move(vs);
  static const char* axis[3] = {"x", "y", "z"};
  // Bézier patches: every term shares its Bernstein basis on each grid line.
  BernsteinOnGrid uBasis(t.u.data(), nu + 1), vBasis(t.v.data(), nv + 1);
  ExpOnGrid uExps(t.u.data(), nu + 1);
  auto vFactor = [&](const VFunction& g, int j, int d) {
    if (g.family != Family::Bernstein) return g.eval(t.v[j], d);
    if (d > g.degree) return 0.0;
    return bernsteinBasisFrom(vBasis.values(g.degree - d) + static_cast<size_t>(j) * (g.degree - d + 1), g.degree, g.n, d);
  };
  std::vector<double> column;
  // cos(w v_j), sin(w v_j) of each frequency w once per grid line: the three coordinates' Fourier
  // terms, and a cosine and a sine of one frequency, share them.
  std::unordered_map<double, std::vector<std::pair<double, double>>> trig;
  const auto trigOf = [&](double w) -> const std::vector<std::pair<double, double>>& {
    auto [it, fresh] = trig.try_emplace(w);
    if (fresh)
      for (int j = 0; j <= nv; ++j) it->second.emplace_back(std::cos(w * t.v[j]), std::sin(w * t.v[j]));
    return it->second;
  };
  for (int c = 0; c < 3; ++c) {
    const auto& terms = s.component[c];
    const int T = static_cast<int>(terms.size());
    t.terms[c] = T;
    t.uTab[c].assign(static_cast<size_t>(nu + 1) * D * T, 0.0);
    t.vTab[c].assign(static_cast<size_t>(nv + 1) * D * T, 0.0);
    for (int k = 0; k < T; ++k) {
      double* uk = t.uTab[c].data() + static_cast<size_t>(D * k) * (nu + 1);
      terms[k].G.tabulate(t.u.data(), nu + 1, maxDerivative, uk, &uBasis, &uExps);
      bool finite = true;
      for (int i = 0; i < D * (nu + 1); ++i) finite = finite && std::isfinite(uk[i]);
      const bool many = terms[k].g.family == Family::General;  // one program run over the grid line, every order
      if (many) {
        column.resize(static_cast<size_t>(nv + 1) * D);
        double* outs[3] = {column.data(), column.data() + (nv + 1), column.data() + 2 * (nv + 1)};
        terms[k].g.general->evalManyUpTo(t.v.data(), nv + 1, D - 1, outs);
        for (int d = 0; d < D; ++d)
          for (int j = 0; j <= nv; ++j) {
            t.vTab[c][static_cast<size_t>(j) * D * T + D * k + d] = outs[d][j];
            finite = finite && std::isfinite(outs[d][j]);
          }
      }
      const Family family = terms[k].g.family;
      const bool bernstein = family == Family::Bernstein, trigonometric = family == Family::Cos || family == Family::Sin;
      const std::vector<std::pair<double, double>>* cs = trigonometric ? &trigOf(terms[k].g.w) : nullptr;
      for (int j = 0; j <= nv && !many; ++j) {
        double* out = t.vTab[c].data() + static_cast<size_t>(j) * D * T + D * k;
        if (bernstein)
          for (int d = 0; d < D; ++d) out[d] = vFactor(terms[k].g, j, d);
        else if (trigonometric)
          terms[k].g.trigUpTo((*cs)[j].first, (*cs)[j].second, D - 1, out);
        else
          terms[k].g.evalUpTo(t.v[j], D - 1, out);
        for (int d = 0; d < D; ++d) finite = finite && std::isfinite(out[d]);
      }
      if (!finite)
        throw Error(ErrorCode::NonFinite, std::string("component ") + axis[c] + ": term " + describeFunction(terms[k].g) +
                                              " is not finite on the grid (v from " + numberText(s.v0) + " to " + numberText(s.v1) + ")");
    }
  }
  for (int c = 0; c < 3; ++c) {
    const Expr& e = s.pointwise[c];
    if (!e) continue;
    const size_t Q = maxDerivative >= 2 ? 6 : 3;
    const auto& pre = s.pointwisePartials[c];
    t.pointwise[c] = pre.size() >= Q ? std::vector<Expr>(pre.begin(), pre.begin() + Q) : partialDerivatives(e, maxDerivative >= 2);
    // The surface's own program (all six partials; the rows read the first Q) when it has one.
    t.pointwiseProgram[c] = pre.size() >= 6 ? pointwiseProgramOf(s, c) : std::make_shared<const ExprProgram>(t.pointwise[c]);
  }
  return t;
}

}  // namespace pdesurf
