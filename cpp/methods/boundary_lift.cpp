#include "methods/boundary_lift.hpp"

#include <Eigen/Dense>
#include <algorithm>

namespace pdesurf {

std::vector<std::vector<double>> hermiteBasis(int n) {
  Eigen::MatrixXd a(2 * n, 2 * n);
  for (int end = 0; end < 2; ++end)
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < 2 * n; ++k) {
        double f = 1.0;  // d^i/du^i u^k at u = end
        for (int q = 0; q < i; ++q) f *= k - q;
        a(end * n + i, k) = k < i ? 0.0 : f * (end == 0 ? (k == i ? 1.0 : 0.0) : 1.0);
      }
  const Eigen::MatrixXd inv = a.inverse();
  std::vector<std::vector<double>> h(2 * n, std::vector<double>(2 * n));
  for (int s = 0; s < 2 * n; ++s)
    for (int k = 0; k < 2 * n; ++k) h[s][k] = inv(k, s);
  return h;
}

void imposeBoundaryData(SeparableSurface& s, const PdeProblem& p) {
  for (int c = 0; c < 3; ++c) {
    const ComponentProblem& cp = p.component[c];
    const int n = static_cast<int>(cp.alpha.size()) - 1;
    if (n < 1) continue;
    const std::vector<std::vector<double>> h = hermiteBasis(n);
    std::vector<SeparableTerm>& terms = s.component[c];
    for (SeparableTerm& t : terms) {
      if (!t.G.bernstein.empty()) continue;  // PDE solutions never have Bernstein factors
      std::vector<double> own(2 * n, 0.0);   // -Σ_s G^(i)(e) h_s
      for (int slot = 0; slot < 2 * n; ++slot) {
        const double d = t.G.eval(slot < n ? 0.0 : 1.0, slot % n);
        for (int k = 0; k < 2 * n; ++k) own[k] -= d * h[slot][k];
      }
      ExpPoly piece;
      piece.poly.assign(own.begin(), own.end());
      t.G.pieces.push_back(piece);
    }
    for (int slot = 0; slot < 2 * n; ++slot) {
      const std::vector<VExpansion>& side = slot < n ? cp.left : cp.right;
      if (slot % n >= static_cast<int>(side.size())) continue;
      for (const VTerm& term : side[slot % n]) {
        ExpPoly piece;
        for (double x : h[slot]) piece.poly.push_back(x * term.coef);
        // A function the surface already has (a family term the approximate solve kept) takes
        // the piece in its u-factor: no new term for tessellation to combine at every vertex.
        auto same = std::find_if(terms.begin(), terms.end(), [&](const SeparableTerm& t) { return t.g == term.g && t.G.bernstein.empty(); });
        if (same != terms.end()) {
          same->G.pieces.push_back(std::move(piece));
        } else {
          UFactor G;
          G.pieces.push_back(std::move(piece));
          terms.push_back({term.g, std::move(G)});
        }
      }
    }
  }
}

}  // namespace pdesurf
