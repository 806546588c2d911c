#include "methods/boundary_lift.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

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

namespace {

// The lift's basis for one coordinate of order 2n: slot s = end*n + i as ExpPoly pieces.
// Without decay the Hermite polynomials; with it, the slots of each decaying end decay away
// from it (see the header), each corrected at the other end by that end's Hermite polynomials.
std::vector<std::vector<ExpPoly>> liftBasis(int n, const LiftDecay& decay) {
  const std::vector<std::vector<double>> h = hermiteBasis(n);
  std::vector<std::vector<ExpPoly>> basis(2 * n);
  for (int slot = 0; slot < 2 * n; ++slot) {
    ExpPoly piece;
    piece.poly.assign(h[slot].begin(), h[slot].end());
    basis[slot].push_back(piece);
  }
  for (int end = 0; end < 2; ++end) {
    const double lambda = end == 0 ? decay.atU0 : decay.atU1;
    if (!(lambda > 0)) continue;
    // e^{r(u-e)} Σ_m c_m (u-e)^m with r = -λ at u = 0, +λ at u = 1 (so it decays into the
    // patch and is never evaluated growing). Its j-th derivative at u = e is
    // Σ_{m<=j} C(j, m) r^{j-m} m! c_m: lower triangular in c.
    const double rate = end == 0 ? -lambda : lambda;
    for (int i = 0; i < n; ++i) {
      std::vector<double> c(n, 0.0);
      for (int j = 0; j < n; ++j) {
        double rest = j == i ? 1.0 : 0.0, binom = 1.0, fact = 1.0;
        for (int m = 0; m < j; ++m) {
          rest -= binom * std::pow(rate, j - m) * fact * c[m];
          binom = binom * (j - m) / (m + 1), fact *= m + 1;
        }
        c[j] = rest / fact;  // C(j, j) = 1, j!
      }
      ExpPoly piece;
      piece.rate = rate;
      piece.shift = end;
      piece.poly.assign(c.begin(), c.end());
      const int slot = end * n + i, far = (1 - end) * n;
      basis[slot] = {piece};
      // Its values at the far end (e^{-λ} there: tiny, but the far end's data are met exactly).
      const double x = (1 - end) - end;  // far end - shift: +1 or -1
      for (int q = 0; q < n; ++q) {
        const double atFar = std::exp(-lambda) * evalPoly(derivativePoly(piece.poly, piece.rate, q), x).real();
        if (atFar == 0.0) continue;
        ExpPoly fix;
        for (double y : h[far + q]) fix.poly.push_back(-atFar * y);
        basis[slot].push_back(fix);
      }
    }
  }
  return basis;
}

// pieces += factor × basis, each basis piece added to a piece of the same rate and shift where
// there is one (a sum of polynomials is one polynomial: fewer pieces to evaluate per u).
void scaleInto(const std::vector<ExpPoly>& basis, double factor, std::vector<ExpPoly>& pieces) {
  for (const ExpPoly& b : basis) {
    auto same = std::find_if(pieces.begin(), pieces.end(), [&](const ExpPoly& q) { return q.rate == b.rate && q.shift == b.shift; });
    if (same == pieces.end()) {
      pieces.push_back({b.rate, b.shift, {}});
      same = pieces.end() - 1;
    }
    if (same->poly.size() < b.poly.size()) same->poly.resize(b.poly.size(), 0.0);
    for (size_t k = 0; k < b.poly.size(); ++k) same->poly[k] += factor * b.poly[k];
  }
}

}  // namespace

void imposeBoundaryData(SeparableSurface& s, const PdeProblem& p, const LiftDecay& decay) {
  for (int c = 0; c < 3; ++c) {
    const ComponentProblem& cp = p.component[c];
    const int n = static_cast<int>(cp.alpha.size()) - 1;
    if (n < 1) continue;
    const std::vector<std::vector<ExpPoly>> basis = liftBasis(n, decay);
    std::vector<SeparableTerm>& terms = s.component[c];
    for (SeparableTerm& t : terms) {
      if (!t.G.bernstein.empty()) continue;  // PDE solutions never have Bernstein factors
      std::vector<double> own(2 * n);        // G^(i)(e) of slot s, taken off below
      for (int slot = 0; slot < 2 * n; ++slot) own[slot] = t.G.eval(slot < n ? 0.0 : 1.0, slot % n);
      for (int slot = 0; slot < 2 * n; ++slot)
        if (own[slot] != 0.0) scaleInto(basis[slot], -own[slot], t.G.pieces);
    }
    for (int slot = 0; slot < 2 * n; ++slot) {
      const std::vector<VExpansion>& side = slot < n ? cp.left : cp.right;
      if (slot % n >= static_cast<int>(side.size())) continue;
      for (const VTerm& term : side[slot % n]) {
        std::vector<ExpPoly> pieces;
        scaleInto(basis[slot], term.coef, pieces);
        // A function the surface already has (a family term the approximate solve kept) takes
        // the piece in its u-factor: no new term for tessellation to combine at every vertex.
        auto same = std::find_if(terms.begin(), terms.end(), [&](const SeparableTerm& t) { return t.g == term.g && t.G.bernstein.empty(); });
        if (same != terms.end()) {
          for (ExpPoly& piece : pieces) same->G.pieces.push_back(std::move(piece));
        } else {
          UFactor G;
          G.pieces = std::move(pieces);
          terms.push_back({term.g, std::move(G)});
        }
      }
    }
  }
}

}  // namespace pdesurf
